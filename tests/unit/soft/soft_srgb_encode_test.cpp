// SPDX-License-Identifier: MIT
// The soft backend's table-driven sRGB encode (engine/render/pixel_codec.hpp) against
// the exact curve it replaces: every stored byte of an sRGB target depends on it.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

#include <gtest/gtest.h>

#include "engine/render/pixel_codec.hpp"

namespace {

namespace codec = engine::render;

// encodeSrgb8 (threshold tables) must give encodeSrgb8Exact's byte for every float. The
// full check of all 2^30 patterns in [0, 1] was run once (seconds); here every 61st
// pattern, every pattern within 4096 of each step, both signs, and the special values.
TEST(SoftSrgbEncode, TableMatchesExactCurve) {
    using codec::encodeSrgb8;
    using codec::encodeSrgb8Exact;
    auto fromBits = [](std::uint32_t b) {
        float f;
        std::memcpy(&f, &b, sizeof f);
        return f;
    };
    int mismatches = 0;
    auto check = [&](std::uint32_t bits) {
        for (std::uint32_t b : {bits, bits | 0x80000000u}) {
            const float f = fromBits(b);
            if (encodeSrgb8(f) != encodeSrgb8Exact(f) && ++mismatches <= 5)
                ADD_FAILURE() << "bits 0x" << std::hex << b << ": table " << int(encodeSrgb8(f)) << ", exact "
                              << int(encodeSrgb8Exact(f));
        }
    };
    constexpr std::uint32_t kOne = 0x3F800000;
    for (std::uint32_t b = 0; b <= kOne; b += 61) check(b);
    const codec::SrgbEncodeTables& tables = codec::srgbEncodeTables();
    for (int k = 1; k < 256; ++k) {
        std::uint32_t step;
        std::memcpy(&step, &tables.threshold[k], sizeof step);
        for (std::uint32_t b = step - std::min<std::uint32_t>(step, 4096); b <= std::min(kOne, step + 4096); ++b)
            check(b);
    }
    for (std::uint32_t b :
         {0u, 1u, 0x007FFFFFu, 0x00800000u, kOne, 0x40000000u, 0x7F7FFFFFu, 0x7F800000u, 0x7FC00000u, 0x7FFFFFFFu})
        check(b);
    EXPECT_EQ(mismatches, 0);
}

// encodeSrgb8 makes one comparison after its bucket's start code: that is right only while
// no bucket of 2^16 float patterns holds two steps of the curve.
TEST(SoftSrgbEncode, NoBucketHoldsTwoSteps) {
    const codec::SrgbEncodeTables& tables = codec::srgbEncodeTables();
    EXPECT_LE(tables.maxBucketSteps, 1);
    EXPECT_EQ(tables.start[codec::kSrgbEncodeBuckets - 1], 255);  // 1.0f's bucket
    EXPECT_EQ(codec::encodeSrgb8(1.0f), 255);
    EXPECT_EQ(codec::encodeSrgb8(std::nextafter(1.0f, 0.0f)), codec::encodeSrgb8Exact(std::nextafter(1.0f, 0.0f)));
}

}  // namespace
