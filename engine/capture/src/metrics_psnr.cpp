// SPDX-License-Identifier: MIT
// RMSE and PSNR of the colour channels, in linear light and after sRGB encoding (metrics.hpp).
#include <algorithm>
#include <cmath>

#include "engine/capture/compare.hpp"
#include "engine/capture/metrics.hpp"
#include "metrics_support.hpp"

namespace engine::capture {
namespace {

using namespace metrics_detail;

// sqrt(mean squared difference) over the three colour channels, each value passed through `map`.
template <typename Map>
double rmse(const Image& reference, const Image& test, std::string_view metric, const Map& map) {
    requireComparable(reference, test, metric);
    const auto ref = colourChannels(reference, metric);
    const auto tst = colourChannels(test, metric);
    const auto width = static_cast<std::size_t>(reference.width);
    const auto channels = static_cast<std::size_t>(reference.channels);
    const double sum = sumRows(reference.height, [&](int y) {
        double rowSum = 0.0;
        const std::size_t row = static_cast<std::size_t>(y) * width;
        for (std::size_t x = 0; x < width; ++x) {
            const float* a = &reference.pixels[(row + x) * channels];
            const float* b = &test.pixels[(row + x) * channels];
            for (std::size_t c = 0; c < 3; ++c) {
                const double d = static_cast<double>(map(a[ref[c]])) - static_cast<double>(map(b[tst[c]]));
                rowSum += d * d;
            }
        }
        return rowSum;
    });
    return std::sqrt(sum / (static_cast<double>(reference.pixelCount()) * 3.0));
}

float identity(float v) { return v; }
float encodeClamped(float v) { return encodeSrgbClamped(v); }

}  // namespace

double rmseLinear(const Image& reference, const Image& test) { return rmse(reference, test, "rmseLinear", identity); }
double psnrLinear(const Image& reference, const Image& test) {
    return psnrFromRms(rmse(reference, test, "psnrLinear", identity), 1.0);
}
double rmseSrgb(const Image& reference, const Image& test) { return rmse(reference, test, "rmseSrgb", encodeClamped); }
double psnrSrgb(const Image& reference, const Image& test) {
    return psnrFromRms(rmse(reference, test, "psnrSrgb", encodeClamped), 1.0);
}

}  // namespace engine::capture
