#pragma once
// `ssam-bench`'s outputs: bench.csv (one row per scene x technique x backend),
// bench_passes.csv (median time of each pass), bench.md (tables and the goal ratios of
// issue #6); bench.svg is bench_chart.hpp's.
#include <filesystem>
#include <string>
#include <vector>

#include "bench_result.hpp"

namespace bench {

struct RunInfo {
    std::string command;  // as typed, for the reports
    int threads = 0;
    int reps = 0, warmup = 0, panFrames = 0;
};

// The columns of bench.csv, in order.
const std::vector<std::string>& csvColumns();

void writeCsv(const std::filesystem::path& path, const std::vector<BenchRow>& rows);
void writePassesCsv(const std::filesystem::path& path, const std::vector<BenchRow>& rows);
void writeMarkdown(const std::filesystem::path& path, const std::vector<BenchRow>& rows, const RunInfo& info);

}  // namespace bench
