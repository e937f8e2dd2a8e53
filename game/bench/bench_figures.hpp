// SPDX-License-Identifier: MIT
#pragma once
// game/bench/FIGURES.md, the figures more than one README quotes, written from one
// ssam-bench run (`--figures FILE`; `make bench` writes the committed file): every scene's
// techniques with time, error, flicker and the per-frame pan error, the goals of
// bench_goals.hpp, the forest in motion and along the dolly (bench_figures_runs.hpp), SSAM
// beside what engines ship (bench_verdict.hpp), and the speed table of
// game/bench/speed_table.sh when given. The prose around the tables quotes no number, so
// nothing in the file can go stale apart from the run that wrote it.
#include <ostream>
#include <string>
#include <vector>

#include "bench_report.hpp"
#include "bench_result.hpp"

namespace bench {

struct FiguresInput {
    RunInfo run;
    int temporalFrames = 0;
    // game/bench/speed_table.sh's table (its speed_table.md), copied in whole; empty: the
    // section says how to get it.
    std::string speedTable;
    std::string speedTableSource;  // the file it came from, named in the section
    // The runs the goals need beside the comparison (bench_figures_runs.hpp); empty when not run.
    // lodRows: the still goals' techniques with the levels of detail the comparison did not use.
    std::vector<BenchRow> lodRows;
    bool lodRowsHaveLevelsOfDetail = true;
    std::vector<MotionRow> motion;
    std::vector<DollyRow> dolly;
};

void writeFigures(std::ostream& out, const std::vector<BenchRow>& rows, const FiguresInput& input);

}  // namespace bench
