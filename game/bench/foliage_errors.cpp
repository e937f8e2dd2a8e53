// SPDX-License-Identifier: MIT
#include "foliage_errors.hpp"

#include <algorithm>
#include <cmath>

#include "engine/capture/metrics.hpp"

namespace bench {

using engine::capture::Image;

std::vector<char> foliagePixels(const Image& reference, const Image& opaque, std::size_t& count) {
    std::vector<char> foliage(std::size_t(reference.width) * reference.height, 0);
    count = 0;
    for (int y = 0; y < reference.height; ++y)
        for (int x = 0; x < reference.width; ++x)
            for (int c = 0; c < 3; ++c)
                if (reference.at(x, y, c) != opaque.at(x, y, c)) {
                    foliage[std::size_t(y) * reference.width + x] = 1;
                    ++count;
                    break;
                }
    return foliage;
}

FoliageError foliageError(const Image& reference, const Image& image, const std::vector<char>& foliage,
                          std::size_t count, Image* flipMap) {
    Image own;
    Image& map = flipMap ? *flipMap : own;
    engine::capture::flip(reference, image, {}, &map);
    double flipSum = 0.0, squares = 0.0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            if (!foliage[std::size_t(y) * image.width + x]) continue;
            flipSum += map.at(x, y, 0);
            for (int c = 0; c < 3; ++c) {
                const double d = double(image.at(x, y, c)) - double(reference.at(x, y, c));
                squares += d * d;
            }
        }
    return {flipSum / double(count), std::sqrt(squares / double(3 * count))};
}

void summarize(std::vector<double> v, double& converged, double& worst) {
    if (v.empty()) return;
    worst = *std::max_element(v.begin(), v.end());
    std::vector<double> tail(v.begin() + std::ptrdiff_t(v.size() / 2), v.end());
    std::sort(tail.begin(), tail.end());
    const std::size_t n = tail.size();
    converged = n % 2 ? tail[n / 2] : 0.5 * (tail[n / 2 - 1] + tail[n / 2]);
}

}  // namespace bench
