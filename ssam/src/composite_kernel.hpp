// SPDX-License-Identifier: MIT
#pragma once
// The soft backend's kernel of SSAM's composite (composite_program.hpp).
#include <cmath>
#include <cstdint>

#include <glm/glm.hpp>

#include "engine/render/kernel/covered_tent.hpp"
#include "engine/render/kernel/fragment.hpp"
#include "engine/render/kernel/sampler.hpp"
#include "engine/render/kernel/texture_lookup.hpp"
#include "ssam/composite_program.hpp"

namespace ssam {

struct CompositeKernel {
    static constexpr engine::render::soft::ProgramNeeds kNeeds{};
    static constexpr bool kReadsPixels = true;
    static constexpr int kRow = 8;  // the rasterizer's block row (raster_support.hpp kBlockSize)
    CompositeParams params;
    const engine::render::soft::SoftTexture* foliage = nullptr;
    const engine::render::soft::SoftTexture* mask = nullptr;
    const engine::render::soft::SoftTexture* maskAdd = nullptr;  // split mask (RG16F precision): ADD mask in r

    CompositeKernel(const CompositeParams& p, const engine::render::soft::TextureLookup& textures)
        : params(p), foliage(textures.texture(p.foliage)), mask(textures.texture(p.mask)),
          maskAdd(textures.texture(p.maskAdd)) {}

    glm::vec4 shade(const engine::render::soft::Fragment& f) const {
        using engine::render::soft::fetchTexel;
        const glm::vec4 m = fetchTexel(*mask, f.x, f.y);
        const float addMask = maskAdd ? fetchTexel(*maskAdd, f.x, f.y).r : m.a;
        float blend = m.r + (addMask - m.r) * params.maskLerp;
        // A float ADD mask exceeds 1 under depth complexity; a factor outside [0,1] would
        // extrapolate past the foliage colour, so it is clamped (NaN becomes 0).
        blend = blend > 0.0f ? (blend < 1.0f ? blend : 1.0f) : 0.0f;
        if (params.squareMask) blend *= blend;  // the squared alpha trick (§3.6.2)
        // A non-finite foliage colour (NaN/Inf from HDR lighting or hostile data) would make
        // the blended result non-finite on float targets; it composites as black instead.
        glm::vec3 color = params.colorBlur ? blurred(f.x, f.y) : glm::vec3(fetchTexel(*foliage, f.x, f.y));
        for (int c = 0; c < 3; ++c)
            if (!std::isfinite(color[c])) color[c] = 0.0f;
        if (fades())
            color = glm::mix(params.foliageClear, color, glm::smoothstep(params.colorFade.x, params.colorFade.y, m.r));
        return {color, blend};
    }
    // Settings::colorFade is on: the colour is not the foliage texture's, so no fast path.
    bool fades() const { return params.colorFade.y > params.colorFade.x; }
    // Settings::colorBlur: the covered neighbours' colour weighted 1-2-1 by 1-2-1, summed in the
    // GLSL's order (composite_blur.glsl); the pixel's own where none was written.
    glm::vec3 blurred(int x, int y) const {
        engine::render::soft::CoveredTentWindow<1> window;
        window.load(*foliage, x, y, 1);
        return window.filtered(0);
    }

    // The rasterizer's composite fast path (raster::hasCompositeHooks): shade()'s alpha, read
    // channel by channel, and its colour: the foliage texel, or with colorBlur the block row's
    // averages (compositeColorRow), each texel decoded once instead of nine times. None (the
    // general path, shade()) when the colour fades.
    const engine::render::soft::SoftTexture* compositeColor() const { return fades() ? nullptr : foliage; }
    bool compositeColorRow(int bx, int py, std::uint32_t live, glm::vec3* out) const {
        if (!params.colorBlur) return false;
        engine::render::soft::CoveredTentWindow<kRow> window;
        window.load(*foliage, bx, py, kRow);
        for (std::uint32_t bits = live; bits; bits &= bits - 1) {
            const int i = __builtin_ctz(bits);
            out[i] = window.filtered(i);
        }
        return true;
    }
    [[gnu::always_inline]] float compositeFactor(int x, int y) const {
        using engine::render::soft::texelChannel;
        const float maxMask = texelChannel(*mask, x, y, 0);
        const float addMask = maskAdd ? texelChannel(*maskAdd, x, y, 0) : texelChannel(*mask, x, y, 3);
        float blend = maxMask + (addMask - maxMask) * params.maskLerp;
        blend = blend > 0.0f ? (blend < 1.0f ? blend : 1.0f) : 0.0f;
        if (params.squareMask) blend *= blend;
        return blend;
    }
};

}  // namespace ssam
