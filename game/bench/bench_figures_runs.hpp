// SPDX-License-Identifier: MIT
#pragma once
// The runs ssam-bench --figures adds after the comparison run, for the goals FIGURES.md states
// (bench_goals.hpp), each on the soft backend with the comparison's size and threads:
//   lodRows  the still goals' techniques (ssam, ssam-paper, ssam-plus, alpha-test) on tree, forest
//            and vista with the levels of detail the comparison did not use: the accuracy goals
//            are measured with --lod off, as before the levels existed, and reported with them on
//            beside (and the reverse when the comparison ran with them on);
//   motion   the forest through the pan, the dolly and the wind (bench_motion.hpp; the wind when
//            the build has modules/wind) for SSAM,
//            SSAM+, alpha testing and what engines ship (bench_verdict.hpp), motion vectors on;
//   dolly    popping along the forest's dolly's first `dollyFrames` frames (bench_dolly.hpp; all
//            of it by default) for SSAM, SSAM+, alpha testing and hashed alpha, with the
//            comparison's crossfade.
// A technique the comparison did not run is left out of these too; its goals then say so.
#include <vector>

#include "bench_result.hpp"
#include "bench_runner.hpp"

namespace bench {

struct FiguresRuns {
    std::vector<BenchRow> lodRows;
    bool lodRowsHaveLevelsOfDetail = true;
    std::vector<MotionRow> motion;
    std::vector<DollyRow> dolly;
};

FiguresRuns runFiguresRuns(const BenchOptions& comparison, int dollyFrames);

}  // namespace bench
