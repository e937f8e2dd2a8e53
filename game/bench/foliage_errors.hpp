// SPDX-License-Identifier: MIT
#pragma once
// The per-frame error measures ssam-bench's temporal and motion runs share: which pixels are
// foliage (where the exact reference differs from the opaque-only frame: the rest is the same
// opaque pass for every technique), ꟻLIP and RMSE over them, and a series' converged and worst.
#include <cstddef>
#include <vector>

#include "engine/capture/image.hpp"

namespace bench {

// 1 where `reference` and `opaque` differ in any colour channel; `count` receives how many.
std::vector<char> foliagePixels(const engine::capture::Image& reference, const engine::capture::Image& opaque,
                                std::size_t& count);

struct FoliageError {
    double flip = 0.0;  // mean ꟻLIP over the foliage pixels
    double rmse = 0.0;  // RMSE of the colour channels (as stored) over the foliage pixels
};
// `image` against `reference` over the `count` (> 0) pixels set in `foliage`; `flipMap`, when
// given, receives the per-pixel ꟻLIP over the whole frame.
FoliageError foliageError(const engine::capture::Image& reference, const engine::capture::Image& image,
                          const std::vector<char>& foliage, std::size_t count,
                          engine::capture::Image* flipMap = nullptr);

// The median of the last half of `v` (the converged value) and its largest element; both
// untouched when `v` is empty.
void summarize(std::vector<double> v, double& converged, double& worst);

}  // namespace bench
