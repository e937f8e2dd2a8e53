// SPDX-License-Identifier: MIT
#pragma once
// TriangleRasterizer's coverage stage: which pixels (and, multisampled, which samples) of a
// tile a triangle covers. 8x8 blocks are trivially rejected or accepted from the edge
// functions at their corners; a partial block's edge functions are stepped exactly, in
// integers, from pixel to pixel.
#include "engine/render/kernel/detail/depth_block_bounds.hpp"
#include "engine/render/kernel/detail/rasterizer/rasterizer_class.hpp"

namespace engine::render::soft {
namespace raster {
namespace {  // as raster_support.hpp's

// Single-sampled targets: the same block test as rasterizeBlock, then whole block rows
// at a time; a partial block's coverage comes from the edge functions stepped exactly
// in integers from pixel to pixel (E(x + 1) = E(x) + a * kPixelStep).
template <typename Program>
inline void TriangleRasterizer<Program>::rasterizeSingle(const SetupTriangle& t, int x0, int y0, int x1, int y1) {
    for (int by = y0 & ~(kBlockSize - 1); by <= y1; by += kBlockSize) {
        const int py0 = std::max(by, y0), py1 = std::min(by + kBlockSize - 1, y1);
        for (int bx = x0 & ~(kBlockSize - 1); bx <= x1; bx += kBlockSize) {
            const int px0 = std::max(bx, x0), px1 = std::min(bx + kBlockSize - 1, x1);
            const std::int64_t xs0 = std::int64_t(px0) * kPixelStep, xs1 = std::int64_t(px1 + 1) * kPixelStep;
            const std::int64_t ys0 = std::int64_t(py0) * kPixelStep, ys1 = std::int64_t(py1 + 1) * kPixelStep;
            bool full = true, reject = false;
            for (int i = 0; i < 3; ++i) {
                const std::int64_t maxE =
                    t.c[i] + t.a[i] * (t.a[i] > 0 ? xs1 : xs0) + t.b[i] * (t.b[i] > 0 ? ys1 : ys0);
                const std::int64_t minE =
                    t.c[i] + t.a[i] * (t.a[i] > 0 ? xs0 : xs1) + t.b[i] * (t.b[i] > 0 ? ys0 : ys1);
                reject = reject || maxE < 0;
                full = full && minE >= 0;
            }
            if (reject) continue;
            if (draw_.depthBounds &&
                draw_.depthBounds->behind(t.depth, t.originX, t.originY, draw_.depthFunc, px0, py0, px1, py1)) {
                ++counters_.depthBlocksSkipped;  // every pixel would fail the depth test
                continue;
            }
            const int n = px1 - px0 + 1, shift = px0 - bx;  // mask bit i: pixel bx + i
            if (full) {
                const std::uint32_t rowMask = ((1u << n) - 1u) << shift;
                if (depthOnlyBlock_ && bx + kBlockSize <= width_) {
                    counters_.pixelsTouched +=
                        depthOnlyBlock_(t, float(bx) + 0.5f, py0, py1, rowMask, depth_.at(bx, py0), depth_.rowBytes);
                    continue;
                }
                if (!draw_.depthTest && draw_.shade) {  // every pixel of the block is live
                    if (constantPending_) {
                        constantPending_ = false;
                        prepareConstant(t, boxPixels_);
                    }
                    if (constant_) {
                        const std::uint64_t pixels = std::uint64_t(kBitCount[rowMask]) * (py1 - py0 + 1);
                        counters_.pixelsTouched += pixels;
                        counters_.pixelsShaded += pixels;
                        if (!constantDiscard_)
                            for (int py = py0; py <= py1; ++py) writeConstantRow(bx, py, rowMask, nullptr, nullptr);
                        continue;
                    }
                }
                for (int py = py0; py <= py1; ++py) shadeRow(t, bx, py, rowMask);
                continue;
            }
            std::int64_t e[3], step[3];
            const std::int64_t x = xs0 + kHalfPixel;
            for (int i = 0; i < 3; ++i) {
                e[i] = t.a[i] * x + t.b[i] * (ys0 + kHalfPixel) + t.c[i];
                step[i] = t.a[i] * kPixelStep;
            }
#if SOFT_RASTER_SSE2
            // The row's pixels two to a vector of 64-bit edge values (pair j: pixels 2j, 2j + 1),
            // stepped down a row by b * kPixelStep; a pixel is covered where the OR of its three
            // values has a clear sign bit, which movemask_pd reads. The integers of the scalar walk
            // below; a lane past the row's n pixels is masked off.
            const int pairs = (n + 1) / 2;
            __m128i pair[3][4], down[3];
            for (int i = 0; i < 3; ++i) {
                const __m128i twoSteps = _mm_set1_epi64x(2 * step[i]);
                pair[i][0] = _mm_set_epi64x(e[i] + step[i], e[i]);
                for (int j = 1; j < pairs; ++j) pair[i][j] = _mm_add_epi64(pair[i][j - 1], twoSteps);
                down[i] = _mm_set1_epi64x(t.b[i] * kPixelStep);
            }
            const std::uint32_t inRow = (1u << n) - 1u;
            for (int py = py0; py <= py1; ++py) {
                std::uint32_t outside = 0;
                for (int j = 0; j < pairs; ++j) {
                    const __m128i any = _mm_or_si128(_mm_or_si128(pair[0][j], pair[1][j]), pair[2][j]);
                    outside |= std::uint32_t(_mm_movemask_pd(_mm_castsi128_pd(any))) << (2 * j);
                    for (int i = 0; i < 3; ++i) pair[i][j] = _mm_add_epi64(pair[i][j], down[i]);
                }
                const std::uint32_t mask = ~outside & inRow;
                if (mask) shadeRow(t, bx, py, mask << shift);
            }
#else
            for (int py = py0; py <= py1; ++py) {
                std::uint32_t mask = 0;
                std::int64_t e0 = e[0], e1 = e[1], e2 = e[2];
                for (int i = 0; i < n; ++i) {
                    mask |= std::uint32_t((e0 | e1 | e2) >= 0) << i;
                    e0 += step[0], e1 += step[1], e2 += step[2];
                }
                if (mask) shadeRow(t, bx, py, mask << shift);
                for (int i = 0; i < 3; ++i) e[i] += t.b[i] * kPixelStep;
            }
#endif
        }
    }
}

// Trivial reject when one edge is negative over the whole block, trivial accept when
// all three are non-negative over it; the block's extent covers every sample position.
template <typename Program>
inline void TriangleRasterizer<Program>::rasterizeBlock(const SetupTriangle& t, int px0, int py0, int px1, int py1) {
    const std::int64_t xs0 = std::int64_t(px0) * kPixelStep, xs1 = std::int64_t(px1 + 1) * kPixelStep;
    const std::int64_t ys0 = std::int64_t(py0) * kPixelStep, ys1 = std::int64_t(py1 + 1) * kPixelStep;
    bool full = true;
    for (int i = 0; i < 3; ++i) {
        const std::int64_t maxE = t.c[i] + t.a[i] * (t.a[i] > 0 ? xs1 : xs0) + t.b[i] * (t.b[i] > 0 ? ys1 : ys0);
        if (maxE < 0) return;
        const std::int64_t minE = t.c[i] + t.a[i] * (t.a[i] > 0 ? xs0 : xs1) + t.b[i] * (t.b[i] > 0 ? ys0 : ys1);
        full = full && minE >= 0;
    }
    if (full) {
        for (int py = py0; py <= py1; ++py)
            for (int px = px0; px <= px1; ++px) shadePixel(t, px, py, allSamples_);
        return;
    }
    for (int py = py0; py <= py1; ++py) {
        for (int px = px0; px <= px1; ++px) {
            const std::uint32_t coverage = sampleCoverage(t, px, py);
            if (coverage) shadePixel(t, px, py, coverage);
        }
    }
}

template <typename Program>
inline std::uint32_t TriangleRasterizer<Program>::sampleCoverage(const SetupTriangle& t, int px, int py) const {
    std::uint32_t mask = 0;
    for (int s = 0; s < pattern_.count; ++s) {
        const std::int64_t x = std::int64_t(px) * kPixelStep + kHalfPixel + pattern_.dx[s] * kSampleOffsetScale;
        const std::int64_t y = std::int64_t(py) * kPixelStep + kHalfPixel + pattern_.dy[s] * kSampleOffsetScale;
        bool inside = true;
        for (int i = 0; i < 3; ++i) inside = inside && (t.a[i] * x + t.b[i] * y + t.c[i] >= 0);
        mask |= std::uint32_t(inside) << s;
    }
    return mask;
}

}  // namespace
}  // namespace raster
}  // namespace engine::render::soft
