#pragma once
// The soft backend's implementation of each ProgramKind. A program is a small struct
// whose `shade` runs per pixel; its `needs` flags let the rasterizer skip interpolating
// what it never reads, which is the seed's dead-code stripping done by hand
// (seeds/000 §3.5.2: the mask program does no lighting and no colour fetch).
#include <cmath>

#include <glm/glm.hpp>

#include "alpha_sampler.hpp"
#include "engine/render/program.hpp"
#include "sampler.hpp"
#include "soft_texture.hpp"

namespace engine::render::soft {

// What the rasterizer hands a program for one pixel (interpolated at its centre).
struct Fragment {
    int x = 0, y = 0;
    glm::vec2 uv{0.0f};
    UvDerivatives duv;
    glm::vec3 normal{0.0f, 0.0f, 1.0f};
    glm::vec4 color{1.0f};
    float clipW = 1.0f;  // clip-space w (the view depth under a perspective projection); set with uv/normal/color
    bool frontFacing = true;
};

struct ProgramNeeds {
    bool uv = false;
    bool derivatives = false;
    bool normal = false;
    bool color = false;       // the vertex colour
    bool colorAlpha = false;  // only its alpha (Fragment::color keeps 1 in r, g, b)
    constexpr bool anyAttribute() const { return uv || normal || color || colorAlpha; }
};

// Texture alpha mode conversion: programs output straight alpha.
inline glm::vec4 toStraight(const glm::vec4& texel, AlphaMode mode) {
    if (mode == AlphaMode::Straight || !(texel.a > 0.0f)) return texel;
    return {glm::vec3(texel) / texel.a, texel.a};
}

// `towardLight` already normalised (glm::normalize(light.towardLight), the same bits
// whether computed per pixel or once per draw).
inline float lambert(const glm::vec3& normal, const glm::vec3& towardLight) {
    const float len = glm::length(normal);
    if (!(len > 0.0f)) return 0.0f;
    return glm::max(glm::dot(normal / len, towardLight), 0.0f);
}
inline float lambert(const glm::vec3& normal, const DirectionalLight& light) {
    return lambert(normal, glm::normalize(light.towardLight));
}

struct FlatProgram {
    static constexpr ProgramNeeds kNeeds{false, false, false, true};
    glm::vec4 color;
    glm::vec4 shade(const Fragment& f) const { return color * f.color; }
};

#if SSAM_ALPHA_SAMPLER_SSE2
// Texture alpha times `factor` times vertex alpha, unclamped, for 4 fragments whose
// interpolated inputs are lanes 0..3 of the arrays (vertex alpha, u, v, and du/dx, dv/dx,
// du/dy, dv/dy in duv[0..3]), for the lanes set in `lanes`: factor * colorA * sampled, in
// the order the programs multiply them.
inline __m128 alphaTimes4(const AlphaSampler& sampler, bool textured, float factor, const float* colorA, const float* u,
                          const float* v, const float* const* duv, std::uint32_t lanes) {
    const __m128 alpha = _mm_mul_ps(_mm_set1_ps(factor), _mm_loadu_ps(colorA));
    if (!textured) return alpha;
    return _mm_mul_ps(alpha, sampler.alpha4(sampler.lookup4(u, v, duv[0], duv[1], duv[2], duv[3], lanes)));
}
#endif

template <bool Foliage>
struct SurfaceProgram {
    static constexpr ProgramNeeds kNeeds{true, true, true, true};
    SurfaceParams params;
    const SoftTexture* texture = nullptr;  // null: white
    glm::vec3 towardLight;                 // hoisted out of the pixel loop
    AlphaSampler alphaSampler;             // Foliage, RGBA8 texture: the alpha alone (alpha4)

    SurfaceProgram(const SurfaceParams& p, const SoftTexture* t)
        : params(p), texture(t), towardLight(glm::normalize(params.light.towardLight)) {
        if constexpr (Foliage)
            if (texture) alphaSampler = AlphaSampler(*texture, params.baseColor.sampler);
    }

#if SSAM_ALPHA_SAMPLER_SSE2
    // The alpha shade() outputs for 4 fragments (see alphaTimes4), with the same bits: the
    // rasterizer alpha-tests with it before shading the colour.
    bool hasAlpha4() const { return Foliage && (!texture || alphaSampler.simd4()); }
    __m128 alpha4(const float* colorA, const float* u, const float* v, const float* const* duv,
                  std::uint32_t lanes) const {
        // base.a = (baseColorFactor.a * vertex alpha) * texel alpha; toStraight keeps alpha.
        return alphaTimes4(alphaSampler, texture != nullptr, params.baseColorFactor.a, colorA, u, v, duv, lanes);
    }
#endif

    glm::vec4 shade(const Fragment& f) const {
        glm::vec4 base = params.baseColorFactor * f.color;
        if (texture) base *= toStraight(sampleTexture(*texture, params.baseColor.sampler, f.uv, f.duv), texture->desc.alpha);
        return light(f, base);
    }
    // shade() with the texture's sample at f given (a texture is bound).
    glm::vec4 shadeSampled(const Fragment& f, const glm::vec4& texel) const {
        glm::vec4 base = params.baseColorFactor * f.color;
        base *= toStraight(texel, texture->desc.alpha);
        return light(f, base);
    }
    glm::vec4 light(const Fragment& f, const glm::vec4& base) const {
        // Foliage is double-sided: a back face is lit with its flipped normal.
        const glm::vec3 n = (Foliage && !f.frontFacing) ? -f.normal : f.normal;
        const glm::vec3 lit = glm::vec3(base) * (params.light.ambient + params.light.color * lambert(n, towardLight));
        return {lit, Foliage ? base.a : 1.0f};
    }
};
using OpaqueLitProgram = SurfaceProgram<false>;
using FoliageColorProgram = SurfaceProgram<true>;

struct FoliageAlphaProgram {
    static constexpr ProgramNeeds kNeeds{true, true, false, false, true};
    AlphaOnlyParams params;
    const SoftTexture* texture = nullptr;
    AlphaSampler alphaSampler;  // valid for RGBA8 textures: the same alpha, read alone

    FoliageAlphaProgram(const AlphaOnlyParams& p, const SoftTexture* t) : params(p), texture(t) {
        if (texture) alphaSampler = AlphaSampler(*texture, params.baseColor.sampler);
    }

    // The replicated value, saturated: the rasterizer's mask path uses it directly.
    [[gnu::always_inline]] float alpha(const Fragment& f) const {
        float a = params.alphaFactor * f.color.a;
        if (texture)
            a *= alphaSampler.valid()
                     ? alphaSampler.sample(f.uv, f.duv)
                     : sampleTexture<SampledChannels::AlphaOnly>(*texture, params.baseColor.sampler, f.uv, f.duv).a;
        return a > 0.0f ? (a < 1.0f ? a : 1.0f) : 0.0f;  // saturate; NaN -> 0
    }
    glm::vec4 shade(const Fragment& f) const {
        return glm::vec4(alpha(f));  // Out.Color.xyzw = Out.Color.www (seeds/000 §3.5.2)
    }

#if SSAM_ALPHA_SAMPLER_SSE2
    // alpha4 may be used.
    bool hasAlpha4() const { return !texture || alphaSampler.simd4(); }
    // alpha() of 4 fragments whose interpolated inputs are lanes 0..3 of the arrays (vertex
    // alpha, u, v, and du/dx, dv/dx, du/dy, dv/dy in duv[0..3]), for the lanes set in `lanes`.
    __m128 alpha4(const float* colorA, const float* u, const float* v, const float* const* duv,
                  std::uint32_t lanes) const {
        const __m128 a = alphaTimes4(alphaSampler, texture != nullptr, params.alphaFactor, colorA, u, v, duv, lanes);
        // As alpha()'s saturate: maxps(a, 0) is 0 for a <= 0 and for NaN, then minps(., 1).
        return _mm_min_ps(_mm_max_ps(a, _mm_setzero_ps()), _mm_set1_ps(1.0f));
    }
#endif
};

// seeds/000 Listing 3.2, one texel per screen pixel (§3.5.4); the lerp with the opaque
// colour is the pipeline's blend (see CompositeParams).
struct CompositeProgram {
    static constexpr ProgramNeeds kNeeds{};
    CompositeParams params;
    const SoftTexture* foliage = nullptr;
    const SoftTexture* mask = nullptr;
    const SoftTexture* maskAdd = nullptr;  // split mask (RG16F precision): ADD mask in r

    glm::vec4 shade(const Fragment& f) const {
        const glm::vec4 m = fetchTexel(*mask, f.x, f.y);
        const float addMask = maskAdd ? fetchTexel(*maskAdd, f.x, f.y).r : m.a;
        float blend = m.r + (addMask - m.r) * params.maskLerp;
        // A float ADD mask exceeds 1 under depth complexity; a factor outside [0,1] would
        // extrapolate past the foliage colour, so it is clamped (NaN becomes 0).
        blend = blend > 0.0f ? (blend < 1.0f ? blend : 1.0f) : 0.0f;
        if (params.squareMask) blend *= blend;  // the squared alpha trick (§3.6.2)
        // A non-finite foliage colour (NaN/Inf from HDR lighting or hostile data) would make
        // the blended result non-finite on float targets; it composites as black instead.
        glm::vec3 color(fetchTexel(*foliage, f.x, f.y));
        for (int c = 0; c < 3; ++c)
            if (!std::isfinite(color[c])) color[c] = 0.0f;
        return {color, blend};
    }
};

// Weighted blended OIT (McGuire & Bavoil, JCGT 2(2), 2013), eq. (7):
//   w(z, a) = a * clamp(10 / (1e-5 + (|z|/5)^2 + (|z|/200)^6), 1e-2, 3e3)
// (program.hpp WboitAccumulateParams). Written out with multiplications only, in the same
// order as the GLSL (gl_shaders.cpp), so both backends round alike. NaN clamps to 1e-2.
inline float wboitWeight(float alpha, float viewDepth) {
    const float z = std::fabs(viewDepth);
    const float near = z / 5.0f, far = z / 200.0f;
    const float far2 = far * far;
    const float g = 10.0f / (1e-5f + near * near + far2 * far2 * far2);
    return alpha * (g > 1e-2f ? (g < 3e3f ? g : 3e3f) : 1e-2f);
}

// FoliageColor's fragment, premultiplied and weighted: (C * a * w, a * w).
struct WboitAccumulateProgram {
    static constexpr ProgramNeeds kNeeds = FoliageColorProgram::kNeeds;
    FoliageColorProgram surface;
    float depthScale = 1.0f;

    glm::vec4 shade(const Fragment& f) const {
        const glm::vec4 c = surface.shade(f);
        const float w = wboitWeight(c.a, f.clipW * depthScale);
        return {glm::vec3(c) * (c.a * w), c.a * w};
    }
};

// The WBOIT composite: (average colour, revealage), blended INV_SRC_ALPHA / SRC_ALPHA onto
// the opaque colour by the pipeline (program.hpp WboitResolveParams).
struct WboitResolveProgram {
    static constexpr ProgramNeeds kNeeds{};
    const SoftTexture* accumulation = nullptr;
    const SoftTexture* revealage = nullptr;

    glm::vec4 shade(const Fragment& f) const {
        const glm::vec4 sum = fetchTexel(*accumulation, f.x, f.y);
        float reveal = fetchTexel(*revealage, f.x, f.y).r;
        reveal = reveal > 0.0f ? (reveal < 1.0f ? reveal : 1.0f) : 0.0f;  // NaN -> 0
        const float weight = sum.a > 1e-5f ? sum.a : 1e-5f;                 // the paper's max(accum.a, 1e-5)
        glm::vec3 average = glm::vec3(sum) / weight;
        for (int c = 0; c < 3; ++c)
            if (!std::isfinite(average[c])) average[c] = 0.0f;
        return {average, reveal};
    }
};

// SSAM+'s composite (program.hpp CoverageCompositeParams): the coverage of the layers from
// the MAX and ADD masks.
inline float layerCoverage(CoverageModel model, float maxMask, float addMask) {
    float coverage = 0.0f;
    if (model == CoverageModel::Exponential) {
        coverage = 1.0f - std::exp(-addMask);
    } else if (maxMask >= 1.0f) {
        coverage = 1.0f;
    } else if (maxMask > 0.0f) {
        coverage = 1.0f - std::pow(1.0f - maxMask, addMask / maxMask);
    }
    return coverage > 0.0f ? (coverage < 1.0f ? coverage : 1.0f) : 0.0f;  // NaN -> 0
}

struct CoverageCompositeProgram {
    static constexpr ProgramNeeds kNeeds{};
    CoverageModel model = CoverageModel::EqualLayers;
    const SoftTexture* foliage = nullptr;
    const SoftTexture* mask = nullptr;
    const SoftTexture* maskAdd = nullptr;

    glm::vec4 shade(const Fragment& f) const {
        const glm::vec4 m = fetchTexel(*mask, f.x, f.y);
        const float addMask = maskAdd ? fetchTexel(*maskAdd, f.x, f.y).r : m.a;
        glm::vec3 color(fetchTexel(*foliage, f.x, f.y));
        for (int c = 0; c < 3; ++c)
            if (!std::isfinite(color[c])) color[c] = 0.0f;
        return {color, layerCoverage(model, m.r, addMask)};
    }
};

}  // namespace engine::render::soft
