// SPDX-License-Identifier: MIT
#pragma once
// Shared plumbing of the metrics (metrics.hpp): argument checks, colour-channel lookup,
// luma, separable filtering and deterministic row-parallel sums. Private to engine_capture.
#include <algorithm>
#include <array>
#include <cmath>
#include <span>
#include <string_view>
#include <vector>

#include "engine/capture/image.hpp"
#include "engine/core/parallel_for.hpp"

namespace engine::capture::metrics_detail {

// Throws engine::Error naming `metric` unless the images match in width, height and channels.
void requireComparable(const Image& reference, const Image& test, std::string_view metric);

// Channel indices of R, G, B (by name when all three exist, else the first three non-alpha
// channels). Throws engine::Error naming `metric` when there are fewer than three.
std::array<int, 3> colourChannels(const Image& image, std::string_view metric);

// Clamps to [0,1] and applies the exact IEC 61966-2-1 encoding curve, evaluated in float
// (powf): within a few ulp of linearToSrgb's double evaluation and several times faster.
inline float encodeSrgbClamped(float linear) {
    const float v = std::clamp(linear, 0.0f, 1.0f);  // NaN stays NaN
    // The affine step in double so that 1 encodes to exactly 1.
    return v <= 0.0031308f ? 12.92f * v
                           : static_cast<float>(1.055 * static_cast<double>(std::pow(v, 1.0f / 2.4f)) - 0.055);
}

// Rec.709 luma of the clamped, sRGB-encoded colour, one float per pixel (row-major).
std::vector<float> srgbLuma(const Image& image, std::string_view metric);

// Runs body(y) for every row in parallel (rows are independent).
template <typename Body>
void forEachRow(int height, const Body& body) {
    parallelForChunks(0, height, 1, [&](int firstRow, int endRow) {
        for (int y = firstRow; y != endRow; ++y) body(y);
    });
}

// Sum over rows of rowSum(y) (a double), rows computed in parallel and added in row order,
// so the result does not depend on how many threads ran.
template <typename RowSum>
double sumRows(int height, const RowSum& rowSum) {
    std::vector<double> partial(static_cast<std::size_t>(height));
    forEachRow(height, [&](int y) { partial[static_cast<std::size_t>(y)] = rowSum(y); });
    double total = 0.0;
    for (const double value : partial) total += value;
    return total;
}

// Separable convolution of a width x height single-channel float plane with clamp-to-edge
// borders: rows with `horizontal`, then columns with `vertical` (both odd-sized, centred).
// `dst` is resized; it must not alias `src`.
void convolveSeparable(std::span<const float> src, std::vector<float>& dst, int width, int height,
                       std::span<const float> horizontal, std::span<const float> vertical);
// One pass of the above, exposed so several vertical kernels can share a horizontal pass.
void convolveRows(std::span<const float> src, std::vector<float>& dst, int width, int height,
                  std::span<const float> kernel);
void convolveColumns(std::span<const float> src, std::vector<float>& dst, int width, int height,
                     std::span<const float> kernel);

}  // namespace engine::capture::metrics_detail
