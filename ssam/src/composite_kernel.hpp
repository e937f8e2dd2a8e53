// SPDX-License-Identifier: MIT
#pragma once
// The soft backend's kernel of SSAM's composite (composite_program.hpp).
#include <cmath>
#include <cstdint>

#if defined(__SSE2__) && !defined(SOFT_RASTER_SCALAR)  // as raster_support.hpp
#include <emmintrin.h>
#define SSAM_COMPOSITE_SSE2 1
#endif

#include <glm/glm.hpp>

#include "engine/render/kernel/covered_tent.hpp"
#include "engine/render/kernel/fragment.hpp"
#include "engine/render/kernel/sampler.hpp"
#include "engine/render/kernel/texture_lookup.hpp"
#include "engine/render/kernel/unorm8x4.hpp"
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
        window.filteredRow(live, out);
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
    // compositeFactor of the block row's 8 pixels from (bx, py) at once (the rasterizer's
    // compositeFactorRow hook), for the usual mask: RGBA8, MAX in red and ADD in alpha, the row
    // inside it. The same operations lane by lane: the bytes over 255 as the unorm table holds
    // them (i / 255.0f, correctly rounded either way), the lerp, the clamp (maxps(b, 0) is 0 for
    // b <= 0 and for NaN, then minps(., 1)) and the square. Reading the factors pixel by pixel
    // took a quarter of the pass at 720p.
    bool compositeFactorRow(int bx, int py, float* out) const {
#if SSAM_COMPOSITE_SSE2
        using engine::render::Format;
        if (maskAdd || mask->desc.format != Format::RGBA8_UNORM || mask->desc.samples != 1 ||
            bx + kRow > mask->desc.width)
            return false;
        const std::byte* row = mask->texel(0, bx, py);
        const __m128 lerp = _mm_set1_ps(params.maskLerp);
        for (int h = 0; h < kRow / 4; ++h) {
            const __m128i texels = _mm_loadu_si128(reinterpret_cast<const __m128i*>(row + 16 * h));
            const __m128 maxMask = engine::render::soft::unorm8x4(texels, 0);
            const __m128 addMask = engine::render::soft::unorm8x4(texels, 24);
            __m128 blend = _mm_add_ps(maxMask, _mm_mul_ps(_mm_sub_ps(addMask, maxMask), lerp));
            blend = _mm_min_ps(_mm_max_ps(blend, _mm_setzero_ps()), _mm_set1_ps(1.0f));
            if (params.squareMask) blend = _mm_mul_ps(blend, blend);
            _mm_storeu_ps(out + 4 * h, blend);
        }
        return true;
#else
        (void)bx, (void)py, (void)out;
        return false;
#endif
    }
};

}  // namespace ssam
