// SPDX-License-Identifier: MIT
#include "metrics_support.hpp"

#include <algorithm>
#include <string>

#include "engine/capture/compare.hpp"
#include "engine/core/error.hpp"

namespace engine::capture::metrics_detail {

void requireComparable(const Image& reference, const Image& test, std::string_view metric) {
    if (reference.empty() || test.empty())
        throw Error(std::string(metric) + ": empty image (" + std::to_string(reference.width) + "x" +
                    std::to_string(reference.height) + " vs " + std::to_string(test.width) + "x" +
                    std::to_string(test.height) + ")");
    const std::string mismatch = describeMismatch(reference, test);
    if (!mismatch.empty()) throw Error(std::string(metric) + ": " + mismatch);
    if (reference.pixels.size() != reference.pixelCount() * static_cast<std::size_t>(reference.channels) ||
        test.pixels.size() != test.pixelCount() * static_cast<std::size_t>(test.channels))
        throw Error(std::string(metric) + ": pixel buffer size does not match width x height x channels");
}

std::array<int, 3> colourChannels(const Image& image, std::string_view metric) {
    const int r = image.channelIndex("R"), g = image.channelIndex("G"), b = image.channelIndex("B");
    if (r >= 0 && g >= 0 && b >= 0 && r < image.channels && g < image.channels && b < image.channels) return {r, g, b};
    std::array<int, 3> found{};
    std::size_t count = 0;
    const int alpha = image.alphaChannel();
    for (int c = 0; c < image.channels && count < found.size(); ++c)
        if (c != alpha) found[count++] = c;
    if (count < found.size())
        throw Error(std::string(metric) + ": needs an RGB(A) image, got " + std::to_string(image.channels) +
                    " channel(s) with " + (alpha >= 0 ? "alpha" : "no alpha"));
    return found;
}

std::vector<float> srgbLuma(const Image& image, std::string_view metric) {
    // Plain names, not a structured binding: capturing those in a lambda is C++20 that Clang 14
    // (the fuzz build, tests/fuzz) does not implement yet.
    const std::array<int, 3> rgb = colourChannels(image, metric);
    const int r = rgb[0], g = rgb[1], b = rgb[2];
    std::vector<float> luma(image.pixelCount());
    const auto width = static_cast<std::size_t>(image.width);
    const auto channels = static_cast<std::size_t>(image.channels);
    auto encode = encodeSrgbClamped;
    forEachRow(image.height, [&](int y) {
        const std::size_t row = static_cast<std::size_t>(y) * width;
        for (std::size_t x = 0; x < width; ++x) {
            const float* p = &image.pixels[(row + x) * channels];
            luma[row + x] = static_cast<float>(0.2126 * static_cast<double>(encode(p[r])) +
                                               0.7152 * static_cast<double>(encode(p[g])) +
                                               0.0722 * static_cast<double>(encode(p[b])));
        }
    });
    return luma;
}

void convolveRows(std::span<const float> src, std::vector<float>& dst, int width, int height,
                  std::span<const float> kernel) {
    const auto w = static_cast<std::size_t>(width);
    const std::size_t radius = kernel.size() / 2;
    dst.assign(w * static_cast<std::size_t>(height), 0.0f);
    forEachRow(height, [&](int y) {
        // The row with `radius` copies of its end values either side (clamp to edge).
        std::vector<float> padded(w + 2 * radius);
        const float* in = &src[static_cast<std::size_t>(y) * w];
        std::fill_n(padded.begin(), radius, in[0]);
        std::copy(in, in + w, padded.begin() + static_cast<std::ptrdiff_t>(radius));
        std::fill_n(padded.begin() + static_cast<std::ptrdiff_t>(radius + w), radius, in[w - 1]);
        float* out = &dst[static_cast<std::size_t>(y) * w];
        for (std::size_t k = 0; k < kernel.size(); ++k) {
            const float weight = kernel[k];
            const float* shifted = padded.data() + k;
            for (std::size_t x = 0; x < w; ++x) out[x] += weight * shifted[x];
        }
    });
}

void convolveColumns(std::span<const float> src, std::vector<float>& dst, int width, int height,
                     std::span<const float> kernel) {
    const auto w = static_cast<std::size_t>(width);
    const int radius = static_cast<int>(kernel.size() / 2);
    dst.assign(w * static_cast<std::size_t>(height), 0.0f);
    forEachRow(height, [&](int y) {
        float* out = &dst[static_cast<std::size_t>(y) * w];
        for (std::size_t k = 0; k < kernel.size(); ++k) {
            const int sy = std::clamp(y + static_cast<int>(k) - radius, 0, height - 1);
            const float weight = kernel[k];
            const float* in = &src[static_cast<std::size_t>(sy) * w];
            for (std::size_t x = 0; x < w; ++x) out[x] += weight * in[x];
        }
    });
}

void convolveSeparable(std::span<const float> src, std::vector<float>& dst, int width, int height,
                       std::span<const float> horizontal, std::span<const float> vertical) {
    std::vector<float> rows;
    convolveRows(src, rows, width, height, horizontal);
    convolveColumns(rows, dst, width, height, vertical);
}

}  // namespace engine::capture::metrics_detail
