// SPDX-License-Identifier: MIT
#pragma once
// The soft backend's kernels of the particle module's programs (particle_programs.hpp).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

#include <glm/glm.hpp>

#include "engine/render/kernel/fragment.hpp"
#include "engine/render/kernel/sampler.hpp"
#include "engine/render/kernel/texture_lookup.hpp"
#include "engine/render/kernel/simd_isa.hpp"
#include "particles/particle_programs.hpp"

namespace particles {

namespace soft = engine::render::soft;

inline float saturateOrZero(float v) { return v > 0.0f ? (v < 1.0f ? v : 1.0f) : 0.0f; }  // NaN -> 0

// The depth of the `stride` x `stride` block of full-resolution texels under layer texel
// (x, y) that is closest to the observer (clamped at the texture's edge).
inline float closestDepth(const soft::SoftTexture& depth, int x, int y, int stride, bool greaterIsCloser) {
    stride = std::clamp(stride, 1, 4);  // the kinds accept 1 or 2; anything else stays in bounds
    const int w = depth.desc.width, h = depth.desc.height;
    float best = soft::fetchTexel(depth, std::min(x * stride, w - 1), std::min(y * stride, h - 1)).r;
    for (int sy = 0; sy < stride; ++sy)
        for (int sx = 0; sx < stride; ++sx) {
            const float z =
                soft::fetchTexel(depth, std::min(x * stride + sx, w - 1), std::min(y * stride + sy, h - 1)).r;
            if (greaterIsCloser ? z > best : z < best) best = z;
        }
    return best;
}

struct ParticleKernel {
    static constexpr soft::ProgramNeeds kNeeds{true, false, true, true};
    static constexpr bool kReadsPixels = true;  // the scene depth at the fragment's pixel
    ParticleParams params;
    const soft::SoftTexture* depth = nullptr;

    ParticleKernel(const ParticleParams& p, const soft::TextureLookup& textures)
        : params(p), depth(textures.texture(p.sceneDepth)) {}

    glm::vec4 shade(const soft::Fragment& f) const {
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

struct LayerCompositeKernel {
    static constexpr soft::ProgramNeeds kNeeds{};
    static constexpr bool kReadsPixels = true;
    LayerCompositeParams params;
    const soft::SoftTexture* layer = nullptr;
    const soft::SoftTexture* depth = nullptr;

    LayerCompositeKernel(const LayerCompositeParams& p, const soft::TextureLookup& textures)
        : params(p), layer(textures.texture(p.layer)), depth(textures.texture(p.sceneDepth)) {}

    glm::vec4 shade(const soft::Fragment& f) const {
        const int lw = layer->desc.width, lh = layer->desc.height;
        const int scale = std::clamp(params.layerScale, 1, 4);
        int lx = std::min(f.x / scale, lw - 1), ly = std::min(f.y / scale, lh - 1);
        if (scale > 1 && depth) {
            const float here = params.depthScale / (soft::fetchTexel(*depth, f.x, f.y).r + params.depthOffset);
            // The 2x2 layer texels around this pixel's centre, nearest first on ties.
            const int x0 = std::clamp((f.x - 1) / 2, 0, lw - 1), y0 = std::clamp((f.y - 1) / 2, 0, lh - 1);
            const int x1 = std::min(x0 + 1, lw - 1), y1 = std::min(y0 + 1, lh - 1);
            const int nx = std::clamp(f.x / 2, 0, lw - 1), ny = std::clamp(f.y / 2, 0, lh - 1);
            // Where the four candidates agree (most of the screen: all empty, or inside one
            // puff) any choice gives the same texel: no depth is read.
            const glm::vec4 c00 = soft::fetchTexel(*layer, x0, y0);
            if (c00 == soft::fetchTexel(*layer, x1, y0) && c00 == soft::fetchTexel(*layer, x0, y1) &&
                c00 == soft::fetchTexel(*layer, x1, y1))
                return finiteLayerTexel(c00);
            float best = std::abs(
                params.depthScale / (closestDepth(*depth, nx, ny, scale, params.greaterIsCloser) + params.depthOffset) -
                here);
            lx = nx, ly = ny;
            for (int cy : {y0, y1})
                for (int cx : {x0, x1}) {
                    const float d = params.depthScale /
                                    (closestDepth(*depth, cx, cy, scale, params.greaterIsCloser) + params.depthOffset);
                    const float diff = std::abs(d - here);
                    if (diff < best) best = diff, lx = cx, ly = cy;
                }
        }
        return finiteLayerTexel(soft::fetchTexel(*layer, lx, ly));
    }

    // The rasterizer's row hook (program_kernel.hpp): shade() of the live pixels of a block
    // row. Most of the composite's region has no particle: where every layer texel shade()
    // would read there is all zero bits, its result is (0, 0, 0, 0) (they are equal, so no
    // depth is read, and each channel decodes to +0), found from the stored halves without
    // decoding them; the rest take shade(). The blend then skips those zeros (the soft
    // backend's zeroSourceKeeps).
    void shadeRow(engine::render::soft::SimdIsa, int bx, int py, std::uint32_t live, glm::vec4* out) const {
        if (layerZeroUnder(bx, py, 8)) {  // the whole row at once, where the layer is empty
            for (std::uint32_t bits = live; bits; bits &= bits - 1) out[__builtin_ctz(bits)] = glm::vec4(0.0f);
            return;
        }
        soft::Fragment f;
        f.y = py;
        for (std::uint32_t bits = live; bits; bits &= bits - 1) {
            const int i = __builtin_ctz(bits);
            f.x = bx + i;
            out[i] = layerZeroUnder(f.x, py, 1) ? glm::vec4(0.0f) : shade(f);
        }
    }

    static glm::vec4 finiteLayerTexel(glm::vec4 c) {
        for (int i = 0; i < 4; ++i)
            if (!std::isfinite(c[i])) c[i] = 0.0f;
        c.a = saturateOrZero(c.a);
        return c;
    }

private:
    // Whether the layer is RGBA16F and every texel shade() reads for the `count` pixels from
    // (x, y) has all its bits zero (other formats answer false: a format without alpha loads
    // alpha 1). The texel columns those pixels read are one run (they do not decrease with x),
    // and so are the rows.
    bool layerZeroUnder(int x, int y, int count) const {
        if (layer->desc.format != engine::render::Format::RGBA16F) return false;
        const int lw = layer->desc.width, lh = layer->desc.height;
        const int scale = std::clamp(params.layerScale, 1, 4);
        int x0, x1, y0, y1;
        if (scale > 1 && depth) {  // shade()'s candidates: (x - 1) / 2 and the next, clamped
            x0 = std::clamp((x - 1) / 2, 0, lw - 1);
            x1 = std::min(std::clamp((x + count - 2) / 2, 0, lw - 1) + 1, lw - 1);
            y0 = std::clamp((y - 1) / 2, 0, lh - 1);
            y1 = std::min(y0 + 1, lh - 1);
        } else {
            x0 = std::min(x / scale, lw - 1), x1 = std::min((x + count - 1) / scale, lw - 1);
            y0 = y1 = std::min(y / scale, lh - 1);
        }
        for (int ly = y0; ly <= y1; ++ly) {
            std::uint64_t bits = 0;
            for (int lx = x0; lx <= x1; ++lx) {
                std::uint64_t stored;
                std::memcpy(&stored, layer->texel(0, lx, ly), sizeof stored);
                bits |= stored;
            }
            if (bits) return false;
        }
        return true;
    }
};

}  // namespace particles
