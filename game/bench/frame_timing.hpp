// SPDX-License-Identifier: MIT
#pragma once
// The two clocks of ssam-bench's rows and the statistic they are reduced to: wall time is
// std::chrono::steady_clock, CPU time the whole process's (every thread a backend runs).
#include <time.h>

#include <algorithm>
#include <cstddef>
#include <vector>

namespace bench {

inline double processCpuMs() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return double(t.tv_sec) * 1e3 + double(t.tv_nsec) * 1e-6;
}

// The median of a non-empty list (the mean of the middle two for an even count).
inline double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

}  // namespace bench
