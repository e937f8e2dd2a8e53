// SPDX-License-Identifier: MIT
#pragma once
// Text helpers shared by ssam-bench's reports (bench.* and sweep.*): numbers as the CSV and
// Markdown print them, quoting, a CSV header line, and staging a report file.
#include <filesystem>
#include <functional>
#include <ostream>
#include <string>
#include <vector>

#include "engine/core/output_file.hpp"

namespace bench {

// Writes the text `write` produces to a temporary file of `files` that becomes `path` when the
// caller commits them all (engine::PendingFiles): reports appear together, whole, or not at all.
void stageReport(engine::PendingFiles& files, const std::filesystem::path& path,
                 const std::function<void(std::ostream&)>& write);

// `v` printed with `format`; NaN (a missing value) as the empty string, infinities as inf/-inf.
// The default prints 9 significant digits: enough to show that two runs are identical.
std::string num(double v, const char* format = "%.9g");

// printf's `format` of the arguments, however long (a CSV line of a report).
[[gnu::format(printf, 1, 2)]] std::string formatted(const char* format, ...);

// A CSV field, quoted when it holds a comma, a quote or a newline.
std::string csvField(const std::string& s);

// A CSV file's first line: the column names, comma-separated.
void writeCsvHeader(std::ostream& out, const std::vector<std::string>& columns);

// A Markdown table cell: pipes escaped, newlines as spaces.
std::string mdCell(const std::string& s);

}  // namespace bench
