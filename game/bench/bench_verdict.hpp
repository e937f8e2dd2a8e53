// SPDX-License-Identifier: MIT
#pragma once
// FIGURES.md's "SSAM and what engines ship": technique `ssam` beside the alpha-tested techniques
// engines ship today at their full strength -- hashed alpha resolved by a TAA with motion vectors
// ([Wyman & McGuire 2017], [Karis 2014]), alpha testing resolved by the same TAA, and alpha to
// coverage sharpened by its screen-space derivative ([Golus 2017]) -- measure by measure: per
// scene the still frame, the pan, the time and the memory (the comparison run's rows), and on the
// forest each motion of ssam-bench --motion (ꟻLIP, ghosting, flicker). Each line names the lowest
// (better) technique; a closing list says, per technique, what it is best at.
#include <ostream>
#include <string>
#include <vector>

#include "bench_result.hpp"

namespace bench {

// The rivals beside `ssam`, in the table's column order.
inline constexpr const char* kShippedTechniques[] = {"hashed+taa", "alpha-test+taa", "a2c-sharp"};

// rowsPage: the page holding the comparison's and the motions' rows, linked from the table's text.
void writeWhatEnginesShip(std::ostream& out, const std::vector<BenchRow>& rows, const std::vector<MotionRow>& motion,
                          const std::string& rowsPage);

}  // namespace bench
