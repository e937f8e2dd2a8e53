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
    const soft::SoftTexture* motion = nullptr;

    TemporalResolveKernel(const TemporalResolveParams& p, const soft::TextureLookup& textures)
        : params(p), current(textures.texture(p.current)), depth(textures.texture(p.depth)),
          history(textures.texture(p.history)), motion(textures.texture(p.motion)) {}

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

    // Where the surface at pixel (x, y), depth d, was in the previous frame, in pixel
    // coordinates times w: the camera's reprojection, plus the surface's own motion `mv`
    // (MotionReprojection) where it has one. Column by column in order (GLSL: the same sums,
    // `precise`).
    glm::vec4 previousOf(int x, int y, float d, const glm::vec4* mv) const {
        const glm::mat4& m = params.reprojection;
        const float px = float(x) + 0.5f, py = float(y) + 0.5f;
        glm::vec4 p = ((m[0] * px + m[1] * py) + m[2] * d) + m[3];
        if (mv) {
            const glm::mat4& q = params.previousToPixels;
            const glm::vec4& r = params.worldW;
            const float w = ((r.x * px + r.y * py) + r.z * d) + r.w;
            p = p + ((q[0] * mv->x + q[1] * mv->y) + q[2] * mv->z) * w;
        }
        return p;
    }

    // The pixel's previous position. Where motion is bound, the motion of the nearest moving
    // surface in the 3x3 neighbourhood, as a screen offset ([Karis 2014]'s closest velocity):
    // a pixel a leaf has just left, or whose surface the leaf's edge only partly covers,
    // follows the leaf, so the leaf's old colour is not fetched in place. The centre first, so
    // that it wins ties; a pixel with no moving surface near follows the camera alone.
    glm::vec2 previousPosition(int x, int y, float d) const {
        int bx = 0, by = 0;
        float bd = d;
        glm::vec4 bmv(0.0f);
        bool found = false;
        if (motion) {
            const int w = motion->desc.width, h = motion->desc.height;
            for (int k = 0; k < 9; ++k) {
                const int nx = x + kNeighbours[k][0], ny = y + kNeighbours[k][1];
                if (nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
                const glm::vec4 mv = soft::fetchTexel(*motion, nx, ny);
                if (!(mv.a > 0.0f)) continue;
                const float nd = soft::fetchTexel(*depth, nx, ny).r;
                if (found && !(params.reverseDepth ? nd > bd : nd < bd)) continue;
                found = true, bx = kNeighbours[k][0], by = kNeighbours[k][1], bd = nd, bmv = mv;
            }
        }
        if (found && (bx != 0 || by != 0)) {
            const glm::vec4 p = previousOf(x + bx, y + by, bd, &bmv);
            const float ox = p.x / p.w - (float(x + bx) + 0.5f), oy = p.y / p.w - (float(y + by) + 0.5f);
            return {(float(x) + 0.5f) + ox, (float(y) + 0.5f) + oy};
        }
        const glm::vec4 p = previousOf(x, y, d, found ? &bmv : nullptr);
        return {p.x / p.w, p.y / p.w};
    }
    static constexpr int kNeighbours[9][2] = {{0, 0}, {-1, -1}, {0, -1}, {1, -1}, {-1, 0},
                                              {1, 0}, {-1, 1},  {0, 1},  {1, 1}};

    glm::vec4 shade(const soft::Fragment& f) const {
        const glm::vec4 c = at(*current, f.x, f.y);
        if (params.copyOnly || !params.hasHistory || !depth || !history) return c;
        const float d = soft::fetchTexel(*depth, f.x, f.y).r;
        const glm::vec2 previous = previousPosition(f.x, f.y, d);
        const float hx = previous.x, hy = previous.y;
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
