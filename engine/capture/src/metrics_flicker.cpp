// SPDX-License-Identifier: MIT
// Temporal flicker: mean |luma(t+1) - luma(t)| over pixels and consecutive frame pairs (metrics.hpp).
#include <cmath>
#include <string>

#include "engine/capture/metrics.hpp"
#include "engine/core/error.hpp"
#include "metrics_support.hpp"

namespace engine::capture {

double temporalFlicker(const std::vector<Image>& frames) {
    if (frames.size() < 2)
        throw Error("temporalFlicker: needs at least two frames, got " + std::to_string(frames.size()));
    for (std::size_t i = 1; i < frames.size(); ++i)
        metrics_detail::requireComparable(frames[0], frames[i], "temporalFlicker (frame " + std::to_string(i) + ")");

    const auto width = static_cast<std::size_t>(frames[0].width);
    double total = 0.0;  // pairs added in order
    std::vector<float> previous = metrics_detail::srgbLuma(frames[0], "temporalFlicker");
    for (std::size_t i = 1; i < frames.size(); ++i) {
        std::vector<float> current = metrics_detail::srgbLuma(frames[i], "temporalFlicker");
        total += metrics_detail::sumRows(frames[0].height, [&](int y) {
            double rowSum = 0.0;
            const std::size_t row = static_cast<std::size_t>(y) * width;
            for (std::size_t x = 0; x < width; ++x)
                rowSum += std::abs(static_cast<double>(current[row + x]) - static_cast<double>(previous[row + x]));
            return rowSum;
        });
        previous = std::move(current);
    }
    return total / (static_cast<double>(frames[0].pixelCount()) * static_cast<double>(frames.size() - 1));
}

}  // namespace engine::capture
