// SPDX-License-Identifier: MIT
#pragma once
// The soft backend's kernel of HashedLit (transparency/hashed_alpha.hpp): the MaskedLit
// surface, then the hashed threshold from the rasterizer's analytic uv derivatives.
#include <glm/glm.hpp>

#include "lod_dither_kernel.hpp"
#include "transparency/hashed_alpha.hpp"

namespace transparency {

struct HashedLitKernel : DitheredSurfaceKernel {
    std::uint32_t seed = 0;
    float hashScale = 1.0f;
    bool anisotropic = false;
    bool outputThreshold = false;

    HashedLitKernel(const HashedLitParams& p, const soft::TextureLookup& textures)
        : DitheredSurfaceKernel(p, textures), seed(p.seed), hashScale(p.hashScale), anisotropic(p.anisotropic),
          outputThreshold(p.outputThreshold) {}

    glm::vec4 shade(const soft::Fragment& f) const {
        // The derivatives are exact for the triangle: d(uv)/dx = (d(uv/w)/dx - uv d(1/w)/dx) w
        // from its planes (the rasterizer's interpolate()); GL takes the same formula over
        // per-quad differences.
        const float t = hashedThreshold(f.uv, f.duv.dx, f.duv.dy, seed, hashScale, anisotropic);
        if (outputThreshold) return {t, t, t, 1.0f};
        // A crossfading instance's other-level pixels have alpha 0, below every threshold.
        const glm::vec4 c = lodDitherOutput(surface.shade(f), f.color.a, dither, f.x, f.y);
        return {glm::vec3(c), c.a >= t ? 1.0f : 0.0f};
    }
};

}  // namespace transparency
