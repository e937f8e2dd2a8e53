// SPDX-License-Identifier: MIT
#include "rss_peak.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <string>

namespace bench {

namespace {

// A "Name:   1234 kB" line of /proc/self/status, in kB; NaN when absent.
double statusKb(const char* name) {
    std::ifstream status("/proc/self/status");
    std::string line;
    const std::string prefix = std::string(name) + ":";
    while (std::getline(status, line))
        if (line.rfind(prefix, 0) == 0) return std::stod(line.substr(prefix.size()));
    return std::numeric_limits<double>::quiet_NaN();
}

}  // namespace

RssPeak::RssPeak() {
    std::ofstream clear("/proc/self/clear_refs");
    clear << "5";
    clear.close();
    startKb_ = clear ? statusKb("VmRSS") : std::numeric_limits<double>::quiet_NaN();
}

double RssPeak::growthMb() const {
    // The kernel updates the high-water mark lazily: a few pages below the start read as 0.
    const double growthKb = statusKb("VmHWM") - startKb_;
    return std::isnan(growthKb) ? growthKb : std::max(0.0, growthKb) / 1024.0;
}

}  // namespace bench
