// SPDX-License-Identifier: MIT
#pragma once
// The soft backend's kernels of the transparency module's programs (programs.hpp).
#include <cmath>
#include <cstdint>

#include <glm/glm.hpp>

#include "engine/render/kernel/clamp01.hpp"
#include "engine/render/kernel/covered_tent.hpp"
#include "engine/render/kernel/fragment.hpp"
#include "engine/render/kernel/programs.hpp"
#include "engine/render/kernel/sampler.hpp"
#include "engine/render/kernel/texture_lookup.hpp"
#include "engine/render/kernel/simd_isa.hpp"
#include "transparency/programs.hpp"

namespace transparency {

namespace soft = engine::render::soft;

using soft::clamp01;

// The composites' guard against a degenerate accumulation reaching the frame: non-finite
// channels to 0 (factors go through clamp01, which takes NaN to 0).
inline glm::vec3 finiteRgb(glm::vec3 c) {
    for (int i = 0; i < 3; ++i)
        if (!std::isfinite(c[i])) c[i] = 0.0f;
    return c;
}

// Weighted blended OIT (McGuire & Bavoil, JCGT 2(2), 2013), eq. (7):
//   w(z, a) = a * clamp(10 / (1e-5 + (|z|/5)^2 + (|z|/200)^6), 1e-2, 3e3)
// (programs.hpp WboitAccumulateParams). Written out with multiplications only, in the same
// order as the GLSL (programs.cpp), so both backends round alike. NaN clamps to 1e-2.
inline float wboitWeight(float alpha, float viewDepth) {
    const float z = std::fabs(viewDepth);
    const float near = z / 5.0f, far = z / 200.0f;
    const float far2 = far * far;
    const float g = 10.0f / (1e-5f + near * near + far2 * far2 * far2);
    return alpha * (g > 1e-2f ? (g < 3e3f ? g : 3e3f) : 1e-2f);
}

// The MaskedLit surface's fragment, premultiplied and weighted: (C * a * w, a * w).
struct WboitAccumulateKernel {
    static constexpr soft::ProgramNeeds kNeeds = soft::MaskedLitProgram::kNeeds;
    soft::MaskedLitProgram surface;
    float depthScale = 1.0f;

    WboitAccumulateKernel(const WboitAccumulateParams& p, const soft::TextureLookup& textures)
        : surface(engine::render::SurfaceParams{p.viewProj, p.baseColorFactor, p.baseColor, p.light}, textures),
          depthScale(p.depthScale) {}

    glm::vec4 shade(const soft::Fragment& f) const {
        const glm::vec4 c = surface.shade(f);
        const float w = wboitWeight(c.a, f.clipW * depthScale);
        return {glm::vec3(c) * (c.a * w), c.a * w};
    }
};

// What the WBOIT and transmittance resolves read at their pixel: an accumulated colour and a
// second target whose red channel is the factor the pipeline blends by, clamped to [0, 1].
struct ColorFactorInputs {
    static constexpr soft::ProgramNeeds kNeeds{};
    static constexpr bool kReadsPixels = true;
    const soft::SoftTexture* color = nullptr;
    const soft::SoftTexture* factor = nullptr;

    glm::vec4 colorAt(const soft::Fragment& f) const { return soft::fetchTexel(*color, f.x, f.y); }
    float factorAt(const soft::Fragment& f) const { return clamp01(soft::fetchTexel(*factor, f.x, f.y).r); }
};

// The WBOIT composite: (average colour, revealage), blended INV_SRC_ALPHA / SRC_ALPHA onto
// the opaque colour by the pipeline (program.hpp WboitResolveParams).
struct WboitResolveKernel : ColorFactorInputs {
    WboitResolveKernel(const WboitResolveParams& p, const soft::TextureLookup& textures)
        : ColorFactorInputs{textures.texture(p.accumulation), textures.texture(p.revealage)} {}

    glm::vec4 shade(const soft::Fragment& f) const {
        const glm::vec4 sum = colorAt(f);
        const float weight = sum.a > 1e-5f ? sum.a : 1e-5f;  // the paper's max(accum.a, 1e-5)
        return {finiteRgb(glm::vec3(sum) / weight), factorAt(f)};
    }
};

// SSAM+'s composite (programs.hpp CoverageCompositeParams): the coverage of the layers from
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
    return clamp01(coverage);
}

// SSAM+'s front layers (programs.hpp CoverageCompositeParams::frontLayers): the colour `kept` of
// the leaf the colour pass kept, of alpha keptAlpha, over the alpha-weighted mean of the layers
// drawn in front of it, `front` = (sum a * C, sum a); `kept` alone where front.a is not > 0. The
// GLSL (glsl/front_layers.glsl) computes it in the same order.
inline glm::vec3 withFrontLayers(glm::vec3 kept, float keptAlpha, glm::vec4 front) {
    if (!(front.a > 0.0f)) return kept;
    const float k = clamp01(keptAlpha);
    return kept * k + glm::vec3(front) / front.a * (1.0f - k);
}

// What both SSAM+ composites read: CoverageCompositeParams' textures, looked up once per draw.
struct CoverageCompositeInputs {
    static constexpr soft::ProgramNeeds kNeeds{};
    static constexpr bool kReadsPixels = true;
    CoverageModel model = CoverageModel::EqualLayers;
    const soft::SoftTexture* foliage = nullptr;
    const soft::SoftTexture* mask = nullptr;
    const soft::SoftTexture* maskAdd = nullptr;
    const soft::SoftTexture* frontLayers = nullptr;

    CoverageCompositeInputs(const CoverageCompositeParams& p, const soft::TextureLookup& textures)
        : model(p.model), foliage(textures.texture(p.foliage)), mask(textures.texture(p.mask)),
          maskAdd(textures.texture(p.maskAdd)), frontLayers(textures.texture(p.frontLayers)) {}

    // The rasterizer's composite fast path (raster::hasCompositeHooks): shade()'s alpha, read
    // channel by channel; the colour is the foliage texel's, or the kernel's compositeColorRow.
    const soft::SoftTexture* compositeColor() const { return foliage; }
    [[gnu::always_inline]] float compositeFactor(int x, int y) const {
        const float maxMask = soft::texelChannel(*mask, x, y, 0);
        const float addMask = maskAdd ? soft::texelChannel(*maskAdd, x, y, 0) : soft::texelChannel(*mask, x, y, 3);
        return layerCoverage(model, maxMask, addMask);
    }

    // shade()'s colour at (x, y) from the kept leaf's colour there (its own or its neighbours')
    // and the alpha of the foliage texel at (x, y).
    glm::vec3 colorAt(glm::vec3 kept, float keptAlpha, int x, int y) const {
        // Most pixels have no layer in front of the kept leaf: their weight alone is read.
        if (!frontLayers || !(soft::texelChannel(*frontLayers, x, y, 3) > 0.0f)) return finiteRgb(kept);
        return finiteRgb(withFrontLayers(kept, keptAlpha, soft::fetchTexel(*frontLayers, x, y)));
    }
    // The fast path's colour, the one shade() gives clamped as the 8-bit target's blend clamps it
    // (blend.hpp): the front layers' mean is not an 8-bit value.
    glm::vec3 compositeColorAt(glm::vec3 kept, float keptAlpha, int x, int y) const {
        const glm::vec3 c = colorAt(kept, keptAlpha, x, y);
        return {clamp01(c.r), clamp01(c.g), clamp01(c.b)};
    }
};

struct CoverageCompositeKernel : CoverageCompositeInputs {
    using CoverageCompositeInputs::CoverageCompositeInputs;

    glm::vec4 shade(const soft::Fragment& f) const {
        const glm::vec4 m = soft::fetchTexel(*mask, f.x, f.y);
        const float addMask = maskAdd ? soft::fetchTexel(*maskAdd, f.x, f.y).r : m.a;
        const glm::vec4 kept = soft::fetchTexel(*foliage, f.x, f.y);
        return {colorAt(glm::vec3(kept), kept.a, f.x, f.y), layerCoverage(model, m.r, addMask)};
    }
    // The composite fast path's colours (raster::hasCompositeColorRow): the foliage texel's
    // (false) unless the front layers are mixed in.
    bool compositeColorRow(int bx, int py, std::uint32_t live, glm::vec3* out) const {
        if (!frontLayers) return false;
        for (std::uint32_t bits = live; bits; bits &= bits - 1) {
            const int i = __builtin_ctz(bits);
            const glm::vec4 kept = soft::fetchTexel(*foliage, bx + i, py);
            out[i] = compositeColorAt(glm::vec3(kept), kept.a, bx + i, py);
        }
        return true;
    }
};

// SSAM+'s blurred composite (programs.hpp CoverageBlurComposite): the same coverage, the
// colour averaged over the written 3x3 neighbours in the order the GLSL sums them.
struct CoverageBlurCompositeKernel : CoverageCompositeInputs {
    using CoverageCompositeInputs::CoverageCompositeInputs;

    glm::vec4 shade(const soft::Fragment& f) const {
        Window window;
        window.load(*foliage, f.x, f.y, 1);
        return blurred(window, window.filtered(0), 0, f.x, f.y);
    }

    // The rasterizer's row hook (program_kernel.hpp): shade() of the live pixels of a block row,
    // each foliage texel of the 3 x (8 + 2) window decoded once instead of once per neighbour
    // (nine times); the sums run in shade()'s order, so the bits are shade()'s. Taken where the
    // composite fast path (compositeColorRow) is not: a float target or foliage.
    void shadeRow(soft::SimdIsa, int bx, int py, std::uint32_t live, glm::vec4* out) const {
        Window window;
        window.load(*foliage, bx, py, kRow);
        glm::vec3 filtered[kRow];
        window.filteredRow(live, filtered);
        for (std::uint32_t bits = live; bits; bits &= bits - 1) {
            const int i = __builtin_ctz(bits);
            out[i] = blurred(window, filtered[i], i, bx + i, py);
        }
    }
    // The composite fast path's colours (raster::hasCompositeColorRow): shadeRow's, without the
    // coverage, which the fast path reads through compositeFactor (the blurred colours are
    // 8-bit means, in [0, 1] as they are).
    bool compositeColorRow(int bx, int py, std::uint32_t live, glm::vec3* out) const {
        Window window;
        window.load(*foliage, bx, py, kRow);
        window.filteredRow(live, out);
        if (frontLayers)
            for (std::uint32_t bits = live; bits; bits &= bits - 1) {
                const int i = __builtin_ctz(bits);
                out[i] = compositeColorAt(out[i], window.texel(1, i + 1).a, bx + i, py);
            }
        return true;
    }

private:
    static constexpr int kRow = 8;  // the rasterizer's block row (raster_support.hpp kBlockSize)
    using Window = soft::CoveredTentWindow<kRow>;

    // Pixel (x, y), column `i` of the window: the covered neighbours' colour, weighted 1-2-1 by
    // 1-2-1 and summed row by row (the GLSL's order: `filtered`, the window's), and SSAM+'s
    // coverage.
    glm::vec4 blurred(const Window& w, glm::vec3 filtered, int i, int x, int y) const {
        const glm::vec4 m = soft::fetchTexel(*mask, x, y);
        const float addMask = maskAdd ? soft::fetchTexel(*maskAdd, x, y).r : m.a;
        return {colorAt(filtered, w.texel(1, i + 1).a, x, y), layerCoverage(model, m.r, addMask)};
    }
};

// (colour, transmittance): the colour as accumulated, the transmittance the blend factor.
struct TransmittanceCompositeKernel : ColorFactorInputs {
    TransmittanceCompositeKernel(const TransmittanceCompositeParams& p, const soft::TextureLookup& textures)
        : ColorFactorInputs{textures.texture(p.color), textures.texture(p.transmittance)} {}

    glm::vec4 shade(const soft::Fragment& f) const { return {finiteRgb(glm::vec3(colorAt(f))), factorAt(f)}; }
};

}  // namespace transparency
