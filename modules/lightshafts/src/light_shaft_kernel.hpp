// SPDX-License-Identifier: MIT
#pragma once
// The soft backend's kernel of the light-shaft program (light_shaft_program.hpp).
#include <algorithm>
#include <cmath>
#include <cstring>

#include <glm/glm.hpp>

#include "engine/render/soft/kernel/fragment.hpp"
#include "engine/render/soft/kernel/texture_lookup.hpp"
#include "lightshafts/light_shaft_program.hpp"

namespace lightshafts {

// The march of light_shaft_program.hpp, written so the GLSL computes the same sample points.
struct LightShaftKernel {
    static constexpr engine::render::soft::ProgramNeeds kNeeds{};
    static constexpr bool kReadsPixels = true;
    LightShaftParams params;
    const engine::render::soft::SoftTexture* depth = nullptr;

    LightShaftKernel(const LightShaftParams& p, const engine::render::soft::TextureLookup& textures)
        : params(p), depth(textures.texture(p.depth)) {}

    float sunGlow(const glm::vec2& q) const {
        if (!(params.glowRadius > 0.0f)) return 1.0f;
        const float t = std::max(0.0f, 1.0f - glm::length(q - params.sunPixel) / params.glowRadius);
        return t * t;
    }

    // The first sample of the march from `p` that may lie within the glow radius. Sample i
    // is at distance d * (1 - density * i / samples) from the sun (d = |p - sun|), so every
    // sample before floor((1 - (glowRadius + 2) / d) * samples / density) is more than 2 px
    // outside the glow, far beyond float rounding: its sunGlow is exactly 0 and adds nothing.
    int firstGlowingSample(const glm::vec2& p, int samples) const {
        if (!(params.glowRadius > 0.0f)) return 0;
        const float d = glm::length(p - params.sunPixel);
        const float first = (1.0f - (params.glowRadius + 2.0f) / d) * float(samples) / params.density;
        return first > 0.0f ? int(std::min(first, float(samples))) : 0;
    }

    glm::vec4 shade(const engine::render::soft::Fragment& f) const {
        const int w = depth->desc.width, h = depth->desc.height;
        const int samples = std::clamp(params.samples, 1, 128);
        const glm::vec2 p(float(f.x) + 0.5f, float(f.y) + 0.5f);
        const glm::vec2 step = (params.sunPixel - p) * (params.density / float(samples));
        // Skipping samples that add 0 leaves every bit as it was: their weights still multiply
        // in, and a skipped sample off the screen means all later ones are too (each
        // coordinate of q moves monotonically away from the on-screen p), so the loop below
        // stops at once as the full march would have.
        const int first = firstGlowingSample(p, samples);
        float sum = 0.0f, weight = 1.0f;
        for (int i = 0; i < first; ++i) weight *= params.decay;
        // D32F and R32F (validated): one float per texel, read in place.
        const std::byte* texels = depth->levels[0].texels.data();
        for (int i = first; i < samples; ++i) {
            const glm::vec2 q = p + step * float(i);
            if (!(q.x >= 0.0f && q.y >= 0.0f && q.x < float(w) && q.y < float(h))) break;  // left the screen
            float z;
            std::memcpy(&z, texels + (std::size_t(int(q.y)) * std::size_t(w) + std::size_t(int(q.x))) * sizeof z, sizeof z);
            const bool sky = params.greaterIsCloser ? !(z > params.farDepth) : !(z < params.farDepth);
            if (sky) sum += weight * sunGlow(q);
            weight *= params.decay;
        }
        glm::vec3 c = params.color * (params.intensity * sum / float(samples));
        for (int i = 0; i < 3; ++i)
            if (!std::isfinite(c[i])) c[i] = 0.0f;
        return {c, 0.0f};
    }
};

}  // namespace lightshafts
