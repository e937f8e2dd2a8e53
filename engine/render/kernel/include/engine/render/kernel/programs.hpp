// SPDX-License-Identifier: MIT
#pragma once
// The soft backend's implementation of each ProgramKind. A program is a small struct
// whose `shade` runs per pixel; its `needs` flags let the rasterizer skip interpolating
// what it never reads, which is the seed's dead-code stripping done by hand
// ([Hathaway 2010] §3.5.2: the mask program does no lighting and no colour fetch).
#include <cmath>

#include <glm/glm.hpp>

#include "alpha_sampler.hpp"
#include "fragment.hpp"
#include "detail/raster_support.hpp"
#include "engine/render/program.hpp"
#include "sampler.hpp"
#include "soft_texture.hpp"
#include "texture_lookup.hpp"

namespace engine::render::soft {

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
    FlatProgram(const FlatParams& p, const TextureLookup&) : color(p.color) {}
    glm::vec4 shade(const Fragment& f) const { return color * f.color; }
};

#if SOFT_SAMPLER_SSE2
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

template <bool AlphaMasked>
struct SurfaceProgram {
    static constexpr ProgramNeeds kNeeds{true, true, true, true};
    SurfaceParams params;
    const SoftTexture* texture = nullptr;  // null: white
    glm::vec3 towardLight;                 // hoisted out of the pixel loop
    AlphaSampler alphaSampler;             // RGBA8 texture: its alpha alone (alpha4), or all four channels (rgba4)

    SurfaceProgram(const SurfaceParams& p, const TextureLookup& textures)
        : SurfaceProgram(p, textures.texture(p.baseColor.texture)) {}
    SurfaceProgram(const SurfaceParams& p, const SoftTexture* t)
        : params(p), texture(t), towardLight(glm::normalize(params.light.towardLight)) {
        if (texture) alphaSampler = AlphaSampler(*texture, params.baseColor.sampler);
    }

#if SOFT_SAMPLER_SSE2
    // The alpha shade() outputs for 4 fragments (see alphaTimes4), with the same bits: the
    // rasterizer alpha-tests with it before shading the colour.
    bool hasAlpha4() const { return AlphaMasked && (!texture || alphaSampler.simd4()); }
    // shade().a == (baseColorFactor.a * vertex alpha) * texel alpha: toStraight keeps alpha.
    // Only an alpha-masked surface has an alpha worth testing first (hasAlphaFirstHooks).
    float alphaTestFactor() const requires AlphaMasked { return params.baseColorFactor.a; }
    // The texture is sampled four fragments at a time (AlphaSampler::rgba4, the general
    // sampler's bits), for shadeSampled().
    const AlphaSampler* rowSampler() const { return texture && alphaSampler.simd4() ? &alphaSampler : nullptr; }
    __m128 alpha4(const float* colorA, const float* u, const float* v, const float* const* duv,
                  std::uint32_t lanes) const {
        // base.a = (baseColorFactor.a * vertex alpha) * texel alpha; toStraight keeps alpha.
        return alphaTimes4(alphaSampler, texture != nullptr, params.baseColorFactor.a, colorA, u, v, duv, lanes);
    }

    // shadeSampled() of 4 fragments, lane i = fragment i, in vectors of one channel: the
    // texel's channels texel[c], the interpolated vertex colour color[c][0..3] and normal
    // normal[k][0..3], into out[c]. Lane by lane the IEEE operations of shadeSampled() in
    // glm's order: componentwise products, dot as (x*x + y*y) + z*z, glm::max(x, 0) as
    // x < 0 ? 0 : x (NaN kept), the normal over its length by division.
    void shadeSampled4(const __m128 (&texel)[4], const float* const (&color)[4], const float* const (&normal)[3],
                       bool frontFacing, __m128 (&out)[4]) const {
        __m128 straight[4] = {texel[0], texel[1], texel[2], texel[3]};
        if (texture->desc.alpha != AlphaMode::Straight) {  // toStraight: rgb / a where a > 0
            const __m128 divide = _mm_cmpgt_ps(texel[3], _mm_setzero_ps());
            for (int c = 0; c < 3; ++c)
                straight[c] =
                    _mm_or_ps(_mm_and_ps(divide, _mm_div_ps(texel[c], texel[3])), _mm_andnot_ps(divide, texel[c]));
        }
        __m128 base[4];
        for (int c = 0; c < 4; ++c)
            base[c] =
                _mm_mul_ps(_mm_mul_ps(_mm_set1_ps(params.baseColorFactor[c]), _mm_loadu_ps(color[c])), straight[c]);
        __m128 n[3];
        const bool flip = AlphaMasked && !frontFacing;  // a back face of a card: its flipped normal
        for (int k = 0; k < 3; ++k) {
            n[k] = _mm_loadu_ps(normal[k]);
            if (flip) n[k] = _mm_xor_ps(n[k], _mm_set1_ps(-0.0f));  // -x, as glm's unary minus
        }
        // lambert(): 0 where !(len > 0), else max(dot(n / len, towardLight), 0).
        const __m128 len =
            _mm_sqrt_ps(_mm_add_ps(_mm_add_ps(_mm_mul_ps(n[0], n[0]), _mm_mul_ps(n[1], n[1])), _mm_mul_ps(n[2], n[2])));
        const __m128 d = _mm_add_ps(_mm_add_ps(_mm_mul_ps(_mm_div_ps(n[0], len), _mm_set1_ps(towardLight.x)),
                                               _mm_mul_ps(_mm_div_ps(n[1], len), _mm_set1_ps(towardLight.y))),
                                    _mm_mul_ps(_mm_div_ps(n[2], len), _mm_set1_ps(towardLight.z)));
        const __m128 below = _mm_cmplt_ps(d, _mm_setzero_ps());
        const __m128 lit = _mm_and_ps(_mm_cmpgt_ps(len, _mm_setzero_ps()), _mm_andnot_ps(below, d));
        for (int c = 0; c < 3; ++c)
            out[c] = _mm_mul_ps(base[c], _mm_add_ps(_mm_set1_ps(params.light.ambient[c]),
                                                    _mm_mul_ps(_mm_set1_ps(params.light.color[c]), lit)));
        out[3] = AlphaMasked ? base[3] : _mm_set1_ps(1.0f);
    }
#endif

    glm::vec4 shade(const Fragment& f) const {
        glm::vec4 base = params.baseColorFactor * f.color;
        if (texture)
            base *= toStraight(sampleTexture(*texture, params.baseColor.sampler, f.uv, f.duv), texture->desc.alpha);
        return light(f, base);
    }
    // shade() with the texture's sample at f given (a texture is bound).
    glm::vec4 shadeSampled(const Fragment& f, const glm::vec4& texel) const {
        glm::vec4 base = params.baseColorFactor * f.color;
        base *= toStraight(texel, texture->desc.alpha);
        return light(f, base);
    }
    glm::vec4 light(const Fragment& f, const glm::vec4& base) const {
        // An alpha-masked surface is double-sided (foliage cards): a back face is lit with its flipped normal.
        const glm::vec3 n = (AlphaMasked && !f.frontFacing) ? -f.normal : f.normal;
        const glm::vec3 lit = glm::vec3(base) * (params.light.ambient + params.light.color * lambert(n, towardLight));
        return {lit, AlphaMasked ? base.a : 1.0f};
    }
};
using OpaqueLitProgram = SurfaceProgram<false>;
using MaskedLitProgram = SurfaceProgram<true>;

struct AlphaOnlyProgram {
    static constexpr ProgramNeeds kNeeds{true, true, false, false, true};
    static constexpr bool kShadesReplicatedAlpha = true;  // shade() == vec4(alpha()): the mask rows
    AlphaOnlyParams params;
    const SoftTexture* texture = nullptr;
    AlphaSampler alphaSampler;  // valid for RGBA8 textures: the same alpha, read alone

    AlphaOnlyProgram(const AlphaOnlyParams& p, const TextureLookup& textures)
        : AlphaOnlyProgram(p, textures.texture(p.baseColor.texture)) {}
    AlphaOnlyProgram(const AlphaOnlyParams& p, const SoftTexture* t) : params(p), texture(t) {
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
        return glm::vec4(alpha(f));  // Out.Color.xyzw = Out.Color.www ([Hathaway 2010] §3.5.2)
    }

#if SOFT_SAMPLER_SSE2
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

}  // namespace engine::render::soft
