// SPDX-License-Identifier: MIT
#pragma once
// A tiny linear congruential generator (Knuth's MMIX constants) for randomized tests: the
// same values on every platform and standard library (std:: distributions differ between
// implementations), so a failing case is reproducible from its seed anywhere.
#include <cstdint>

namespace ssam::testing {

struct Lcg {
    std::uint64_t state;
    std::uint32_t next() {
        state = state * 6364136223846793005ull + 1442695040888963407ull;
        return std::uint32_t(state >> 33);
    }
    float unit() { return float(next() & 0xFFFFFF) / float(0x1000000); }  // [0, 1)
    float range(float lo, float hi) { return lo + (hi - lo) * unit(); }
};

}  // namespace ssam::testing
