#pragma once
// Text helpers shared by ssam-bench's reports (bench.* and sweep.*): numbers as the CSV and
// Markdown print them, quoting, and opening an output file with a clear error.
#include <filesystem>
#include <fstream>
#include <string>

namespace bench {

std::ofstream openOut(const std::filesystem::path& path);

// `v` printed with `format`; NaN (a missing value) as the empty string, infinities as inf/-inf.
// The default prints 9 significant digits: enough to show that two runs are identical.
std::string num(double v, const char* format = "%.9g");

// A CSV field, quoted when it holds a comma, a quote or a newline.
std::string csvField(const std::string& s);

// A Markdown table cell: pipes escaped, newlines as spaces.
std::string mdCell(const std::string& s);

}  // namespace bench
