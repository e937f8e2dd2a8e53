// SPDX-License-Identifier: MIT
#include "tile_rasterizer.hpp"

#include <algorithm>

#include "engine/render/kernel/program_kernel.hpp"

namespace engine::render::soft {

using raster::kHalfPixel;
using raster::kPixelStep;
using raster::kSampleOffsetScale;

const SamplePattern& samplePattern(int samples) {
    static const SamplePattern k1{1, {0}, {0}};
    static const SamplePattern k2{2, {4, -4}, {4, -4}};
    static const SamplePattern k4{4, {-2, 6, -6, 2}, {-6, -2, 2, 6}};
    static const SamplePattern k8{8, {1, -1, 5, -3, -5, -7, 3, 7}, {-3, 3, 1, -5, 5, -1, 7, -7}};
    switch (samples) {
        case 2: return k2;
        case 4: return k4;
        case 8: return k8;
        default: return k1;
    }
}

void rasterizeTile(const Rect& tile, std::span<const SetupTriangle* const> triangles,
                   const std::vector<DrawState>& draws, TileCounters& counters) {
    std::size_t i = 0;
    while (i < triangles.size()) {
        // A run of triangles from one draw shares the program instance and its state.
        const std::uint32_t drawIndex = triangles[i]->drawIndex;
        std::size_t end = i + 1;
        while (end < triangles.size() && triangles[end]->drawIndex == drawIndex) ++end;
        const DrawState& draw = draws[drawIndex];
        draw.program->rasterize(draw, triangles.subspan(i, end - i), tile, counters);
        i = end;
    }
}

bool isTinyTriangle(const SetupTriangle& t) { return (t.maxX - t.minX) < 2 && (t.maxY - t.minY) < 2; }

bool coversAnySample(const SetupTriangle& t, const SamplePattern& pattern) {
    for (int py = t.minY; py <= t.maxY; ++py)
        for (int px = t.minX; px <= t.maxX; ++px)
            for (int s = 0; s < pattern.count; ++s) {
                const std::int64_t x = std::int64_t(px) * kPixelStep + kHalfPixel + pattern.dx[s] * kSampleOffsetScale;
                const std::int64_t y = std::int64_t(py) * kPixelStep + kHalfPixel + pattern.dy[s] * kSampleOffsetScale;
                bool inside = true;
                for (int i = 0; i < 3; ++i) inside = inside && (t.a[i] * x + t.b[i] * y + t.c[i] >= 0);
                if (inside) return true;
            }
    return false;
}

void binTriangle(const SetupTriangle& t, std::uint32_t triangle, const TileGrid& grid, std::vector<BinEntry>& out) {
    // A tiny triangle that covers no sample never gets here: set-up, given the pass's sample
    // pattern (Viewport::pattern), has dropped it (and a full-screen one covers every sample).
    const int ts = grid.tileSize;
    const int tx0 = t.minX / ts, tx1 = t.maxX / ts, ty0 = t.minY / ts, ty1 = t.maxY / ts;
    if (tx0 == tx1 && ty0 == ty1) {  // the common small triangle: its box is in one tile
        out.push_back({std::uint32_t(ty0 * grid.tilesX + tx0), triangle});
        return;
    }
    for (int ty = ty0; ty <= ty1; ++ty) {
        const int py0 = std::max(ty * ts, t.minY), py1 = std::min(ty * ts + ts - 1, t.maxY);
        const std::int64_t ys0 = std::int64_t(py0) * kPixelStep, ys1 = std::int64_t(py1 + 1) * kPixelStep;
        for (int tx = tx0; tx <= tx1; ++tx) {
            const int px0 = std::max(tx * ts, t.minX), px1 = std::min(tx * ts + ts - 1, t.maxX);
            const std::int64_t xs0 = std::int64_t(px0) * kPixelStep, xs1 = std::int64_t(px1 + 1) * kPixelStep;
            bool reject = false;
            for (int i = 0; i < 3; ++i)
                reject = reject || t.c[i] + t.a[i] * (t.a[i] > 0 ? xs1 : xs0) + t.b[i] * (t.b[i] > 0 ? ys1 : ys0) < 0;
            if (!reject) out.push_back({std::uint32_t(ty * grid.tilesX + tx), triangle});
        }
    }
}

}  // namespace engine::render::soft
