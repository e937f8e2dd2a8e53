// SPDX-License-Identifier: MIT
#pragma once
// game/bench/FIGURES.md, the figures more than one README quotes, written from one
// ssam-bench run (`--figures FILE`; `make bench` writes the committed file): the goals of
// bench_goals.hpp, the forest along the dolly (bench_figures_runs.hpp), SSAM beside what
// engines ship (bench_verdict.hpp), and the speed table of game/bench/speed_table.sh when
// given; and beside it FIGURES_ROWS.md, every scene's techniques with time, error, flicker and
// the per-frame pan error, and every technique in the forest's motions. The prose around the tables quotes no number, so
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
    // The rows page's file name as FIGURES.md links it (beside it: rowsPagePath's name).
    std::string rowsPage = "FIGURES_ROWS.md";
};

// The page beside `figuresPath` that holds every row: its name with "_ROWS" before the
// extension (game/bench/FIGURES.md -> game/bench/FIGURES_ROWS.md).
std::string rowsPagePath(const std::string& figuresPath);

// FIGURES.md into `out` (the speed table, the goals met or not and what limits those not met,
// the dolly's popping, SSAM beside what engines ship) and the rows they come from into
// `rowsOut` (every scene's techniques, every technique in motion), each page naming the run.
void writeFigures(std::ostream& out, std::ostream& rowsOut, const std::vector<BenchRow>& rows,
                  const FiguresInput& input);

}  // namespace bench
