// SPDX-License-Identifier: MIT
#pragma once
// `ssam-bench --sweep`'s outputs: sweep.csv (one row per scene x backend x setting, the knobs
// and the same measure columns as bench.csv) and sweep.md (per scene: the settings sorted by
// ꟻLIP with the defaults and the best marked, how far each knob alone moves the error, and
// the techniques measured beside them).
#include <ostream>
#include <string>
#include <vector>

#include "bench_report.hpp"
#include "bench_sweep.hpp"

namespace bench {

// The columns of sweep.csv, in order.
const std::vector<std::string>& sweepCsvColumns();

void writeSweepCsv(std::ostream& out, const std::vector<SweepResult>& results);
void writeSweepMarkdown(std::ostream& out, const SweepRun& run, const RunInfo& info);

}  // namespace bench
