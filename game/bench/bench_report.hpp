// SPDX-License-Identifier: MIT
#pragma once
// `ssam-bench`'s outputs: bench.csv (one row per scene x technique x backend),
// bench_passes.csv (median time of each pass), bench.md (tables and the goal ratios of SSAM
// against its rivals); bench.svg is bench_chart.hpp's. Each is written to a stream; ssam-bench
// stages the files and puts them in place together (report_text.hpp stageReport).
#include <ostream>
#include <string>
#include <vector>

#include "bench_result.hpp"

namespace bench {

struct RunInfo {
    std::string command;  // as typed, for the reports
    int threads = 0;
    int reps = 0, warmup = 0, panFrames = 0;
    std::string ssamPreset;  // technique ssam's knobs (ssam::Preset); empty: not said
};

// The columns of bench.csv, in order.
const std::vector<std::string>& csvColumns();

void writeCsv(std::ostream& out, const std::vector<BenchRow>& rows);
void writePassesCsv(std::ostream& out, const std::vector<BenchRow>& rows);
void writeMarkdown(std::ostream& out, const std::vector<BenchRow>& rows, const RunInfo& info);

}  // namespace bench
