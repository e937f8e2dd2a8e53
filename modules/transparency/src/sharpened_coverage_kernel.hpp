// SPDX-License-Identifier: MIT
#pragma once
// The soft backend's kernel of SharpenedCoverageLit (transparency/sharpened_coverage.hpp): the
// MaskedLit surface, then its alpha sharpened by the fine derivative of a 2x2 quad, taken from
// the texture at the quad partners' uv (this pixel's uv moved by its analytic derivatives).
#include <cmath>

#include <glm/glm.hpp>

#include "lod_dither_kernel.hpp"
#include "transparency/sharpened_coverage.hpp"

namespace transparency {

struct SharpenedCoverageLitKernel : DitheredSurfaceKernel {
    float reference = 0.5f;

    SharpenedCoverageLitKernel(const SharpenedCoverageParams& p, const soft::TextureLookup& textures)
        : DitheredSurfaceKernel(p, textures), reference(p.reference) {}

    glm::vec4 shade(const soft::Fragment& f) const {
        // A crossfading batch: sharpened without its weight, then the other level's pixels dropped.
        const float weight = f.color.a;
        const glm::vec4 c = lodFadeRemoved(surface.shade(f), weight, dither);
        float width = 0.0f;
        if (surface.texture) {  // without one, alpha is the factor's times the vertex's: flat
            // The quad's fine differences: x even pairs with x + 1, x odd with x - 1 (the
            // difference always taken right minus left, bottom minus top; fwidth's abs makes
            // the sign moot).
            const float stepX = (f.x & 1) ? -1.0f : 1.0f, stepY = (f.y & 1) ? -1.0f : 1.0f;
            const float scale = surface.params.baseColorFactor.a * f.color.a;
            const float ax =
                lodFadeRemoved({0, 0, 0, texelAlpha(f.uv + stepX * f.duv.dx, f) * scale}, weight, dither).a;
            const float ay =
                lodFadeRemoved({0, 0, 0, texelAlpha(f.uv + stepY * f.duv.dy, f) * scale}, weight, dither).a;
            width = std::abs(ax - c.a) + std::abs(ay - c.a);
        }
        return lodDitherDropped({glm::vec3(c), sharpenedCoverage(c.a, width, reference)}, weight, dither, f.x, f.y);
    }

private:
    float texelAlpha(glm::vec2 uv, const soft::Fragment& f) const {
        return soft::sampleTexture(*surface.texture, surface.params.baseColor.sampler, uv, f.duv).a;
    }
};

}  // namespace transparency
