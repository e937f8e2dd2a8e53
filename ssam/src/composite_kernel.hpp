// SPDX-License-Identifier: MIT
#pragma once
// The soft backend's kernel of SSAM's composite (composite_program.hpp).
#include <cmath>

#include <glm/glm.hpp>

#include "engine/render/kernel/fragment.hpp"
#include "engine/render/kernel/sampler.hpp"
#include "engine/render/kernel/texture_lookup.hpp"
#include "ssam/composite_program.hpp"

namespace ssam {

struct CompositeKernel {
    static constexpr engine::render::soft::ProgramNeeds kNeeds{};
    static constexpr bool kReadsPixels = true;
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
    // Settings::colorBlur: the written neighbours' colour weighted 1-2-1 by 1-2-1, summed in the
    // GLSL's order (composite.glsl); the pixel's own where none was written.
    glm::vec3 blurred(int x, int y) const {
        using engine::render::soft::fetchTexel;
        glm::vec3 sum(0.0f);
        float weights = 0.0f;
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
                const int qx = x + dx, qy = y + dy;
                if (qx < 0 || qy < 0 || qx >= foliage->desc.width || qy >= foliage->desc.height) continue;
                const glm::vec4 c = fetchTexel(*foliage, qx, qy);
                if (!(c.a > 0.0f)) continue;
                const float weight = float((2 - dx * dx) * (2 - dy * dy));
                sum += weight * glm::vec3(c);
                weights += weight;
            }
        return weights > 0.0f ? sum / weights : glm::vec3(fetchTexel(*foliage, x, y));
    }

    // The rasterizer's composite fast path (raster::hasCompositeHooks): shade()'s alpha, read
    // channel by channel.
    // None (the general path, shade()) when the colour fades or is averaged.
    const engine::render::soft::SoftTexture* compositeColor() const {
        return fades() || params.colorBlur ? nullptr : foliage;
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
