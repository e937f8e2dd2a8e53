// SPDX-License-Identifier: MIT
#pragma once
// The nearest and farthest depth stored in each 8x8 block of a single-sampled D32F target, for a
// pass whose draws test depth and none writes it (a mask pass, SSAM+'s front layers, ...): the
// depth then cannot change while the pass runs, and a triangle whose depth plane lies behind
// every stored depth of a block (as its compare function sees it) fails the test at every pixel
// of that block, so the rasterizer skips the block before its rows. The skip is exact: the
// plane's extreme over the block's pixel centres is taken at its corners, with the depth row's
// operations in its order (depthRow, raster_support.hpp), widened by a margin that covers any
// rounding the compiler's choice of instructions could add; a block with a NaN stored, or a
// plane that is not finite, is never skipped. What is skipped would have written nothing and
// counted nothing (pixelsTouched counts pixels that pass the depth test).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <limits>
#include <vector>

#if defined(__SSE2__) && !defined(SOFT_RASTER_SCALAR)  // as raster_support.hpp
#include <emmintrin.h>
#define SOFT_DEPTH_BOUNDS_SSE2 1
#endif

#include "engine/render/compare_func.hpp"
#include "engine/render/kernel/detail/triangle_setup.hpp"

namespace engine::render::soft {

class DepthBlockBounds {
public:
    static constexpr int kBlock = 8;  // the rasterizer's block (raster_support.hpp kBlockSize)

    // The block grid of a width x height target.
    void resize(int width, int height) {
        blocksX_ = (width + kBlock - 1) / kBlock;
        blocksY_ = (height + kBlock - 1) / kBlock;
        nearest_.resize(std::size_t(blocksX_) * blocksY_);
        farthest_.resize(nearest_.size());
    }
    int blockRows() const { return blocksY_; }
    // The bounds of `depth` (width x height floats, `rowBytes` apart) for block rows [rowBegin,
    // rowEnd) of the grid resize() made: each block row may be built by another thread.
    void buildRows(const std::byte* depth, std::size_t rowBytes, int width, int height, int rowBegin, int rowEnd) {
        for (int by = rowBegin; by < rowEnd; ++by) {
            const int y0 = by * kBlock, y1 = std::min(height, y0 + kBlock);
            for (int bx = 0; bx < blocksX_; ++bx) {
                const int x0 = bx * kBlock, x1 = std::min(width, x0 + kBlock);
                const std::size_t i = std::size_t(by) * blocksX_ + bx;
                const Range r = x1 - x0 == kBlock ? fullRowsRange(depth, rowBytes, x0, y0, y1)
                                                  : range(depth, rowBytes, x0, x1, y0, y1);
                constexpr float inf = std::numeric_limits<float>::infinity();
                nearest_[i] = r.nan ? -inf : r.lo;  // a NaN block: no plane is ever behind it
                farthest_[i] = r.nan ? inf : r.hi;
            }
        }
    }

    // Whether the plane `depth` (a set-up triangle's, origin (originX, originY)) fails `func`
    // against every stored depth at every pixel centre of columns px0..px1, rows py0..py1 of one
    // block. Only the ordering functions skip; any other answers false.
    bool behind(const Plane& depth, float originX, float originY, CompareFunc func, int px0, int py0, int px1,
                int py1) const {
        if (!(std::isfinite(depth.value) && std::isfinite(depth.dx) && std::isfinite(depth.dy))) return false;
        // As depthRow: z = (value + dx * fx) + dy * fy, fx = (px + 0.5) - originX, clamped to [0, 1].
        const float fx[2] = {(float(px0) + 0.5f) - originX, (float(px1) + 0.5f) - originX};
        const float fy[2] = {(float(py0) + 0.5f) - originY, (float(py1) + 0.5f) - originY};
        float lo = std::numeric_limits<float>::infinity(), hi = -lo;
        for (float x : fx)
            for (float y : fy) {
                const float z = (depth.value + depth.dx * x) + depth.dy * y;
                lo = std::min(lo, z);
                hi = std::max(hi, z);
            }
        const float magnitude = std::fabs(depth.value) +
                                std::fabs(depth.dx) * std::max(std::fabs(fx[0]), std::fabs(fx[1])) +
                                std::fabs(depth.dy) * std::max(std::fabs(fy[0]), std::fabs(fy[1]));
        const float margin = 1e-6f * (1.0f + magnitude);
        const std::size_t i = std::size_t(py0 / kBlock) * blocksX_ + std::size_t(px0 / kBlock);
        // std::clamp keeps a NaN (clamp01 would make it 0), and a NaN compares false: no skip.
        const float nearZ = std::clamp(lo - margin, 0.0f, 1.0f), farZ = std::clamp(hi + margin, 0.0f, 1.0f);
        switch (func) {
            case CompareFunc::Less: return nearZ >= farthest_[i];
            case CompareFunc::LessEqual: return nearZ > farthest_[i];
            case CompareFunc::Greater: return farZ <= nearest_[i];
            case CompareFunc::GreaterEqual: return farZ < nearest_[i];
            default: return false;
        }
    }

private:
    struct Range {
        float lo, hi;
        bool nan;
    };
    static const float* row(const std::byte* depth, std::size_t rowBytes, int x, int y) {
        return reinterpret_cast<const float*>(depth + std::size_t(y) * rowBytes) + x;
    }
    static Range range(const std::byte* depth, std::size_t rowBytes, int x0, int x1, int y0, int y1) {
        Range r{std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity(), false};
        for (int y = y0; y < y1; ++y)
            for (int x = x0; x < x1; ++x) {
                const float d = *row(depth, rowBytes, x, y);
                r.nan = r.nan || std::isnan(d);
                r.lo = std::min(r.lo, d);
                r.hi = std::max(r.hi, d);
            }
        return r;
    }
    // range() of a block 8 wide, four lanes at a time (the same minimum and maximum: neither
    // depends on the order, and a NaN marks the block whichever lane it is in).
    static Range fullRowsRange(const std::byte* depth, std::size_t rowBytes, int x0, int y0, int y1) {
#if SOFT_DEPTH_BOUNDS_SSE2
        __m128 lo = _mm_set1_ps(std::numeric_limits<float>::infinity()), hi = _mm_sub_ps(_mm_setzero_ps(), lo);
        __m128 nan = _mm_setzero_ps();
        for (int y = y0; y < y1; ++y) {
            const float* p = row(depth, rowBytes, x0, y);
            for (int h = 0; h < 2; ++h) {
                const __m128 d = _mm_loadu_ps(p + 4 * h);
                nan = _mm_or_ps(nan, _mm_cmpunord_ps(d, d));
                lo = _mm_min_ps(lo, d);
                hi = _mm_max_ps(hi, d);
            }
        }
        alignas(16) float l[4], u[4];
        _mm_store_ps(l, lo);
        _mm_store_ps(u, hi);
        return {std::min(std::min(l[0], l[1]), std::min(l[2], l[3])),
                std::max(std::max(u[0], u[1]), std::max(u[2], u[3])), _mm_movemask_ps(nan) != 0};
#else
        return range(depth, rowBytes, x0, x0 + kBlock, y0, y1);
#endif
    }

    int blocksX_ = 0, blocksY_ = 0;
    std::vector<float> nearest_, farthest_;  // per block, row by row
};

}  // namespace engine::render::soft
