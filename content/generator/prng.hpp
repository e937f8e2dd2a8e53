// SPDX-License-Identifier: MIT
#pragma once
// The generator's only source of randomness: PCG32 (O'Neill, pcg-random.org, "pcg32" =
// PCG-XSH-RR with 64-bit state). Every draw is integer arithmetic and the float helpers use
// exact scalings, so a seed gives the same sequence with every compiler and standard library
// (std::uniform_*_distribution does not promise that).
#include <cstdint>

namespace content {

class Pcg32 {
public:
    explicit Pcg32(std::uint64_t seed, std::uint64_t stream = 0x853c49e6748fea9bULL) {
        inc_ = (stream << 1u) | 1u;
        next();
        state_ += seed;
        next();
    }

    std::uint32_t next() {
        const std::uint64_t old = state_;
        state_ = old * 6364136223846793005ULL + inc_;
        const auto xorshifted = static_cast<std::uint32_t>(((old >> 18u) ^ old) >> 27u);
        const auto rot = static_cast<std::uint32_t>(old >> 59u);
        return (xorshifted >> rot) | (xorshifted << ((32u - rot) & 31u));
    }

    // [0, 1) with 24 random bits: exact in float.
    float uniform() { return static_cast<float>(next() >> 8) * (1.0f / 16777216.0f); }
    float uniform(float lo, float hi) { return lo + (hi - lo) * uniform(); }
    // [0, n) without modulo bias worth caring about for the small n used here.
    std::uint32_t below(std::uint32_t n) {
        return static_cast<std::uint32_t>((static_cast<std::uint64_t>(next()) * n) >> 32);
    }

private:
    std::uint64_t state_ = 0;
    std::uint64_t inc_ = 0;
};

// A stateless hash of lattice coordinates (for value noise): the PCG output function on a
// mixed 64-bit key.
inline std::uint32_t hash3(std::int32_t x, std::int32_t y, std::uint32_t seed) {
    std::uint64_t h = static_cast<std::uint64_t>(static_cast<std::uint32_t>(x)) * 0x9E3779B97F4A7C15ULL ^
                      static_cast<std::uint64_t>(static_cast<std::uint32_t>(y)) * 0xC2B2AE3D27D4EB4FULL ^
                      static_cast<std::uint64_t>(seed) * 0x165667B19E3779F9ULL;
    h ^= h >> 29;
    h *= 0xBF58476D1CE4E5B9ULL;
    h ^= h >> 32;
    return static_cast<std::uint32_t>(h);
}

}  // namespace content
