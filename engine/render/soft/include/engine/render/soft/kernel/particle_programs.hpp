#pragma once
// The soft backend's Particle and LayerComposite programs (program.hpp ParticleParams,
// LayerCompositeParams; modules/particles): premultiplied output so alpha-blended and
// additive particles share one layer (seeds/003), soft particles against the opaque +
// foliage depth, closest-sample depth for half-resolution layers (seeds/000 §3.5.1) and a
// nearest-depth upsample in the composite.
#include <algorithm>
#include <cmath>
#include <cstring>

#include <glm/glm.hpp>

#include "engine/render/depth_state.hpp"
#include "engine/render/program.hpp"
#include "sampler.hpp"
#include "soft_texture.hpp"

namespace engine::render::soft {

inline float saturateOrZero(float v) { return v > 0.0f ? (v < 1.0f ? v : 1.0f) : 0.0f; }  // NaN -> 0

// The depth of the `stride` x `stride` block of full-resolution texels under layer texel
// (x, y) that is closest to the observer (clamped at the texture's edge).
inline float closestDepth(const SoftTexture& depth, int x, int y, int stride, bool greaterIsCloser) {
    stride = std::clamp(stride, 1, 4);  // the kinds accept 1 or 2; anything else stays in bounds
    const int w = depth.desc.width, h = depth.desc.height;
    float best = fetchTexel(depth, std::min(x * stride, w - 1), std::min(y * stride, h - 1)).r;
    for (int sy = 0; sy < stride; ++sy)
        for (int sx = 0; sx < stride; ++sx) {
            const float z = fetchTexel(depth, std::min(x * stride + sx, w - 1), std::min(y * stride + sy, h - 1)).r;
            if (greaterIsCloser ? z > best : z < best) best = z;
        }
    return best;
}

struct ParticleProgram {
    static constexpr ProgramNeeds kNeeds{true, false, true, true};
    ParticleParams params;
    const SoftTexture* depth = nullptr;

    glm::vec4 shade(const Fragment& f) const {
        const glm::vec2 q = f.uv * 2.0f - 1.0f;
        const float shape = saturateOrZero(1.0f - (q.x * q.x + q.y * q.y));
        float fade = 1.0f;
        if (depth) {
            const float z = closestDepth(*depth, f.x, f.y, params.depthStride, params.greaterIsCloser);
            const float sceneDistance = params.depthScale / (z + params.depthOffset);
            fade = saturateOrZero((sceneDistance - f.normal.x) / params.softness);
        }
        const float a = saturateOrZero(f.color.a) * shape * fade;
        const float additive = saturateOrZero(f.normal.y);
        glm::vec4 out(glm::vec3(f.color) * a, a * (1.0f - additive));
        for (int c = 0; c < 4; ++c)
            if (!std::isfinite(out[c])) out[c] = 0.0f;
        return out;
    }
};

struct LayerCompositeProgram {
    static constexpr ProgramNeeds kNeeds{};
    LayerCompositeParams params;
    const SoftTexture* layer = nullptr;
    const SoftTexture* depth = nullptr;

    glm::vec4 shade(const Fragment& f) const {
        const int lw = layer->desc.width, lh = layer->desc.height;
        const int scale = std::clamp(params.layerScale, 1, 4);
        int lx = std::min(f.x / scale, lw - 1), ly = std::min(f.y / scale, lh - 1);
        if (scale > 1 && depth) {
            const float here = params.depthScale / (fetchTexel(*depth, f.x, f.y).r + params.depthOffset);
            // The 2x2 layer texels around this pixel's centre, nearest first on ties.
            const int x0 = std::clamp((f.x - 1) / 2, 0, lw - 1), y0 = std::clamp((f.y - 1) / 2, 0, lh - 1);
            const int x1 = std::min(x0 + 1, lw - 1), y1 = std::min(y0 + 1, lh - 1);
            const int nx = std::clamp(f.x / 2, 0, lw - 1), ny = std::clamp(f.y / 2, 0, lh - 1);
            // Where the four candidates agree (most of the screen: all empty, or inside one
            // puff) any choice gives the same texel: no depth is read.
            const glm::vec4 c00 = fetchTexel(*layer, x0, y0);
            if (c00 == fetchTexel(*layer, x1, y0) && c00 == fetchTexel(*layer, x0, y1) &&
                c00 == fetchTexel(*layer, x1, y1))
                return finiteLayerTexel(c00);
            float best = std::abs(params.depthScale /
                                      (closestDepth(*depth, nx, ny, scale, params.greaterIsCloser) +
                                       params.depthOffset) -
                                  here);
            lx = nx, ly = ny;
            for (int cy : {y0, y1})
                for (int cx : {x0, x1}) {
                    const float d = params.depthScale /
                                    (closestDepth(*depth, cx, cy, scale, params.greaterIsCloser) +
                                     params.depthOffset);
                    const float diff = std::abs(d - here);
                    if (diff < best) best = diff, lx = cx, ly = cy;
                }
        }
        return finiteLayerTexel(fetchTexel(*layer, lx, ly));
    }

    static glm::vec4 finiteLayerTexel(glm::vec4 c) {
        for (int i = 0; i < 4; ++i)
            if (!std::isfinite(c[i])) c[i] = 0.0f;
        c.a = saturateOrZero(c.a);
        return c;
    }
};

// seeds/000 §3.7 lists light shafts among the passes after the foliage; program.hpp
// LightShaftParams. The march is written so GL computes the same sample points.
struct LightShaftsProgram {
    static constexpr ProgramNeeds kNeeds{};
    LightShaftParams params;
    const SoftTexture* depth = nullptr;

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

    glm::vec4 shade(const Fragment& f) const {
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

}  // namespace engine::render::soft
