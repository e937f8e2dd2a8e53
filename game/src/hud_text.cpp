// SPDX-License-Identifier: MIT
#include "hud_text.hpp"

#include <cstdio>

namespace racer {

namespace {

std::string format(const char* pattern, auto... values) {
    char buf[160];
    std::snprintf(buf, sizeof buf, pattern, values...);
    return buf;
}

// What the backend's pass timings are (engine/render/backend.hpp PassTiming).
const char* passClock(const std::string& backend) {
    if (backend.rfind("soft", 0) == 0) return "CPU wall time of each pass";
    // The GLES driver's (natively and in the web page) are CPU times: ES 3.0 has no timer query.
    if (backend.rfind("gles", 0) == 0) return "CPU time recording each pass (ES: no timer query)";
    return "GPU time of each pass (GL_TIME_ELAPSED)";
}

}  // namespace

std::vector<std::string> hudLines(const HudFacts& f) {
    std::vector<std::string> lines;
    lines.push_back(format("%s | %s | %dx%d", f.technique.c_str(), f.backend.c_str(), f.width, f.height));
    if (!f.extra.empty()) lines.push_back(f.extra);
    if (f.frameMs < 0.0) {
        lines.push_back("frame time: none yet (first frame)");
        return lines;
    }
    lines.push_back(format("frame %.1f ms (%.1f fps), %s, wall clock", f.frameMs,
                           f.frameMs > 0.0 ? 1000.0 / f.frameMs : 0.0, f.timeSpan.c_str()));
    if (f.transientBytes >= 0)
        lines.push_back(format("transient targets: peak %lld bytes (%.1f KiB), previous frame",
                               static_cast<long long>(f.transientBytes), double(f.transientBytes) / 1024.0));
    if (!f.levelsOfDetail.empty()) lines.push_back(f.levelsOfDetail);
    if (f.passes.empty()) return lines;
    lines.push_back(format("passes, ms: %s", passClock(f.backend)));
    for (const auto& p : f.passes)
        lines.push_back(p.skipped ? format("  skipped  %s", p.pass.c_str())
                                  : format("  %7.2f  %s", p.milliseconds, p.pass.c_str()));
    return lines;
}

std::string lodCountsLine(const engine::scene::DrawLists& lists) {
    const auto& n = lists.instancesAtLevel;
    if (n[0] + n[1] + n[2] == 0) return {};
    return format("levels of detail: %u full, %u middle, %u impostor", n[0], n[1], n[2]);
}

std::string compareHudLine(const std::string& left, const std::string& right) {
    return "side by side: " + left + " | " + right + " (passes: " + right + "'s frame, then " + left + "'s)";
}

}  // namespace racer
