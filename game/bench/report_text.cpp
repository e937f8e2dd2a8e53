// SPDX-License-Identifier: MIT
#include "report_text.hpp"

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "engine/core/error.hpp"

namespace bench {

void stageReport(engine::PendingFiles& files, const std::filesystem::path& path,
                 const std::function<void(std::ostream&)>& write) {
    std::ostringstream text;
    write(text);
    std::ofstream out(files.add(path), std::ios::binary);
    out << text.str();
    out.close();
    if (!out) throw engine::Error("cannot write '" + path.string() + "'");
}

std::string num(double v, const char* format) {
    if (std::isnan(v)) return "";
    if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
    char buf[64];
    std::snprintf(buf, sizeof buf, format, v);
    return buf;
}

std::string formatted(const char* format, ...) {
    std::va_list args, again;
    va_start(args, format);
    va_copy(again, args);
    const int size = std::vsnprintf(nullptr, 0, format, args);
    va_end(args);
    std::string out(std::size_t(std::max(size, 0)), '\0');
    if (size > 0) std::vsnprintf(out.data(), out.size() + 1, format, again);
    va_end(again);
    return out;
}

std::string csvField(const std::string& s) {
    if (s.find_first_of(",\"\n") == std::string::npos) return s;
    std::string q = "\"";
    for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c == '\n' ? ' ' : c);
    return q + "\"";
}

void writeCsvHeader(std::ostream& out, const std::vector<std::string>& columns) {
    for (std::size_t i = 0; i < columns.size(); ++i) out << (i ? "," : "") << columns[i];
    out << "\n";
}

std::string mdCell(const std::string& s) {
    std::string r;
    for (char c : s) r += c == '|' ? std::string("\\|") : std::string(1, c == '\n' ? ' ' : c);
    return r;
}

}  // namespace bench
