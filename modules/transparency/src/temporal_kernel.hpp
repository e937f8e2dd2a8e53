// SPDX-License-Identifier: MIT
#pragma once
// The soft backend's kernel of TemporalResolve (transparency/temporal.hpp). The GLSL in
// temporal_program.cpp performs the same operations in the same order.
#include <cmath>

#include <glm/glm.hpp>

#include "engine/render/kernel/fragment.hpp"
#include "engine/render/kernel/sampler.hpp"
#include "engine/render/kernel/texture_lookup.hpp"
#include "transparency/temporal.hpp"

namespace transparency {

namespace soft = engine::render::soft;

struct TemporalResolveKernel {
    static constexpr soft::ProgramNeeds kNeeds{};
    static constexpr bool kReadsPixels = true;
    TemporalResolveParams params;
    const soft::SoftTexture* current = nullptr;
    const soft::SoftTexture* depth = nullptr;
    const soft::SoftTexture* history = nullptr;

    TemporalResolveKernel(const TemporalResolveParams& p, const soft::TextureLookup& textures)
        : params(p), current(textures.texture(p.current)), depth(textures.texture(p.depth)),
          history(textures.texture(p.history)) {}

    static glm::vec4 finite(glm::vec4 c) {
        for (int i = 0; i < 4; ++i)
            if (!std::isfinite(c[i])) c[i] = 0.0f;
        return c;
    }
    static glm::vec4 at(const soft::SoftTexture& t, int x, int y) {
        const int w = t.desc.width, h = t.desc.height;
        x = x < 0 ? 0 : (x >= w ? w - 1 : x);
        y = y < 0 ? 0 : (y >= h ? h - 1 : y);
        return finite(soft::fetchTexel(t, x, y));
    }

    glm::vec4 shade(const soft::Fragment& f) const {
        const glm::vec4 c = at(*current, f.x, f.y);
        if (params.copyOnly || !params.hasHistory || !depth || !history) return c;
        const float d = soft::fetchTexel(*depth, f.x, f.y).r;
        const glm::mat4& m = params.reprojection;
        const float px = float(f.x) + 0.5f, py = float(f.y) + 0.5f;
        // m * (px, py, d, 1), column by column in order (GLSL: the same sums, `precise`).
        const glm::vec4 p = ((m[0] * px + m[1] * py) + m[2] * d) + m[3];
        const float hx = p.x / p.w, hy = p.y / p.w;
        const float w = float(history->desc.width), h = float(history->desc.height);
        if (!(hx >= 0.0f && hx <= w && hy >= 0.0f && hy <= h)) return c;  // off screen or not finite
        // Bilinear: texel centres at + 0.5.
        const float sx = hx - 0.5f, sy = hy - 0.5f;
        const float x0 = std::floor(sx), y0 = std::floor(sy);
        const float fx = sx - x0, fy = sy - y0;
        const int ix = int(x0), iy = int(y0);
        const glm::vec4 top = at(*history, ix, iy) * (1.0f - fx) + at(*history, ix + 1, iy) * fx;
        const glm::vec4 bottom = at(*history, ix, iy + 1) * (1.0f - fx) + at(*history, ix + 1, iy + 1) * fx;
        const glm::vec4 hist = top * (1.0f - fy) + bottom * fy;
        glm::vec4 lo = c, hi = c;
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
                const glm::vec4 n = at(*current, f.x + dx, f.y + dy);
                lo = glm::min(lo, n);
                hi = glm::max(hi, n);
            }
        const glm::vec4 clamped = glm::min(glm::max(hist, lo), hi);
        return clamped + (c - clamped) * params.blend;  // exactly c where the history agrees
    }
};

}  // namespace transparency
