// SPDX-License-Identifier: MIT
#pragma once
// The soft backend's kernel of the light-shaft program (light_shaft_program.hpp).
#include <algorithm>
#include <cmath>
#include <cstring>

#include <glm/glm.hpp>

#include "engine/render/kernel/fragment.hpp"
#include "engine/render/kernel/texture_lookup.hpp"
#include "engine/render/kernel/simd_isa.hpp"
#include "lightshafts/light_shaft_program.hpp"

namespace lightshafts {

struct LightShaftKernel;
namespace sse2 {
void marchRow(const LightShaftKernel& kernel, int bx, int py, std::uint32_t live, glm::vec4* out);
}
namespace avx2 {
void marchRow(const LightShaftKernel& kernel, int bx, int py, std::uint32_t live, glm::vec4* out);
}

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
        const int samples = sampleCount();
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
            std::memcpy(&z, texels + (std::size_t(int(q.y)) * std::size_t(w) + std::size_t(int(q.x))) * sizeof z,
                        sizeof z);
            const bool sky = params.greaterIsCloser ? !(z > params.farDepth) : !(z < params.farDepth);
            if (sky) sum += weight * sunGlow(q);
            weight *= params.decay;
        }
        return colorOf(sum);
    }

    int sampleCount() const { return std::clamp(params.samples, 1, 128); }
    // What a pixel adds, from its march's sum.
    glm::vec4 colorOf(float sum) const {
        glm::vec3 c = params.color * (params.intensity * sum / float(sampleCount()));
        for (int i = 0; i < 3; ++i)
            if (!std::isfinite(c[i])) c[i] = 0.0f;
        return {c, 0.0f};
    }

    // The rasterizer's row hook (raster::hasRowShader): shade() of pixel (bx + i, py) into
    // out[i] for each lane i set in `live`, a block row's 8 pixels marched together
    // (light_shaft_march.inl), with the same bits.
    void shadeRow(engine::render::soft::SimdIsa isa, int bx, int py, std::uint32_t live, glm::vec4* out) const {
#if defined(__SSE2__) && !defined(SOFT_RASTER_SCALAR)
        // The wide march indexes texels with 32-bit ints.
        if (std::size_t(depth->desc.width) * std::size_t(depth->desc.height) < (std::size_t(1) << 31)) {
            if (isa == engine::render::soft::SimdIsa::Avx2) avx2::marchRow(*this, bx, py, live, out);
            else sse2::marchRow(*this, bx, py, live, out);
            return;
        }
#endif
        (void)isa;
        for (std::uint32_t bits = live; bits; bits &= bits - 1) {
            const int i = __builtin_ctz(bits);
            engine::render::soft::Fragment f;
            f.x = bx + i;
            f.y = py;
            out[i] = shade(f);
        }
    }
};

}  // namespace lightshafts
