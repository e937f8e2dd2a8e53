// SPDX-License-Identifier: MIT
#include "report_text.hpp"

#include <cmath>
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

std::string csvField(const std::string& s) {
    if (s.find_first_of(",\"\n") == std::string::npos) return s;
    std::string q = "\"";
    for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c == '\n' ? ' ' : c);
    return q + "\"";
}

std::string mdCell(const std::string& s) {
    std::string r;
    for (char c : s) r += c == '|' ? std::string("\\|") : std::string(1, c == '\n' ? ' ' : c);
    return r;
}

}  // namespace bench
