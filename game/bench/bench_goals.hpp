// SPDX-License-Identifier: MIT
#pragma once
// The goals SSAM is held to against the techniques engines ship today (game/bench/bench.md):
// each a ratio of two rows of one ssam-bench run, with its target and whether it was met.
// bench.md and FIGURES.md (bench_figures.hpp) print the same list.
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "bench_result.hpp"

namespace bench {

// The row named `ssam` with the paper's knobs, which ssam-bench --with-paper-ssam adds beside
// technique ssam's recommended preset: the time goal's denominator.
inline constexpr const char* kSsamPaperRow = "ssam-paper";

struct Goal {
    std::string what;             // e.g. "forest: ꟻLIP ssam / alpha-test"
    std::optional<double> ratio;  // the measure; unset: a row is missing from the run
    double target = 0.0;          // the measure must be at most this (below it when `below`)
    std::string missing;          // when ratio is unset: what the run lacked
    bool below = false;           // "below the rival's": strictly less than the target
    bool isRatio = true;          // a ratio of two rows (printed 0.500x), else a value of one row
    // The document and section that work out what limits this goal, named where it is not met.
    std::string limitedBy = {};
    bool met() const { return ratio && (below ? *ratio < target : *ratio <= target); }
};

// From the rows of the primary backend (soft when it ran): per scene with foliage (tree,
// forest, vista), SSAM's ꟻLIP at most alpha testing's and its time at most 1.25x the paper
// preset's; SSAM+'s ꟻLIP at most 0.6x alpha testing's; in the forest, SSAM's flicker at most
// 0.3x alpha testing's.
std::vector<Goal> rivalGoals(const std::vector<BenchRow>& rows);

// The goals in motion ([Hathaway 2010] §3.4: motion is where alpha testing sparkles), from
// ssam-bench --motion's rows on the forest, for each motion measured (pan, dolly, wind): SSAM's
// flicker at most 0.3x alpha testing's and SSAM+'s converged ꟻLIP at most 0.6x alpha testing's.
std::vector<Goal> motionGoals(const std::vector<MotionRow>& rows);

// The levels of detail's goals along the forest's dolly (ssam-bench --dolly's rows): SSAM's
// popping (pop_lod, the change the levels add to the motion's own) below alpha testing's and
// below hashed alpha's, and its LOD frame's mean ꟻLIP against full detail at most 0.02.
std::vector<Goal> dollyGoals(const std::vector<DollyRow>& rows);

// "What limits ...": each measured goal not met, with its measure and its Goal::limitedBy; or
// that every measured goal is met.
void writeGoalLimits(std::ostream& out, const std::vector<Goal>& goals);

// | goal | measured | target | met? |; with `beside`, two more columns: the same goals measured
// in another run (matched by `what`), headed by `besideName`.
void writeGoalTable(std::ostream& out, const std::vector<Goal>& goals, const std::vector<Goal>* beside = nullptr,
                    const std::string& besideName = "");

// The backend the goals and the chart are computed on: soft when it ran (deterministic errors).
std::string primaryBackend(const std::vector<BenchRow>& rows);

const BenchRow* findRow(const std::vector<BenchRow>& rows, const std::string& scene, const std::string& technique,
                        const std::string& backend);

}  // namespace bench
