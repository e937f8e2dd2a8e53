#include "report_text.hpp"

#include <cmath>
#include <cstdio>

#include "engine/core/error.hpp"

namespace bench {

std::ofstream openOut(const std::filesystem::path& path) {
    std::ofstream out(path);
    if (!out) throw engine::Error("ssam-bench: cannot write '" + path.string() + "'");
    return out;
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
