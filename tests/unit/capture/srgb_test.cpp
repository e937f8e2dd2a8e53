// SPDX-License-Identifier: MIT
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "engine/capture/srgb.hpp"

using namespace engine::capture;

namespace {
// The IEC 61966-2-1 decode in double: the reference the table must reproduce.
double referenceDecode(int code) {
    const double v = code / 255.0;
    return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}
}  // namespace

TEST(CaptureSrgb, DecodeMatchesTheExactCurveForAll256Codes) {
    for (int code = 0; code < 256; ++code)
        EXPECT_EQ(decodeSrgb8(static_cast<std::uint8_t>(code)), static_cast<float>(referenceDecode(code)))
            << "code " << code;
    EXPECT_EQ(decodeSrgb8(0), 0.0f);
    EXPECT_EQ(decodeSrgb8(255), 1.0f);
}

TEST(CaptureSrgb, EncodeOfDecodeIsIdentityForAll256Codes) {
    for (int code = 0; code < 256; ++code)
        EXPECT_EQ(encodeSrgb8(decodeSrgb8(static_cast<std::uint8_t>(code))), code) << "code " << code;
}

TEST(CaptureSrgb, EncodeRoundsToTheNearestCode) {
    // Just either side of the midpoint between two codes' linear values (midpoint taken in encoded space).
    for (int code = 0; code < 255; ++code) {
        const double midEncoded = (code + 0.5) / 255.0;
        const double midLinear =
            midEncoded <= 0.04045 ? midEncoded / 12.92 : std::pow((midEncoded + 0.055) / 1.055, 2.4);
        EXPECT_EQ(encodeSrgb8(static_cast<float>(midLinear * (1.0 - 1e-5))), code) << "below mid " << code;
        EXPECT_EQ(encodeSrgb8(static_cast<float>(midLinear * (1.0 + 1e-5))), code + 1) << "above mid " << code;
    }
}

TEST(CaptureSrgb, EncodeClampsAndWritesNanAsZero) {
    EXPECT_EQ(encodeSrgb8(-0.5f), 0);
    EXPECT_EQ(encodeSrgb8(7.0f), 255);
    EXPECT_EQ(encodeSrgb8(std::numeric_limits<float>::infinity()), 255);
    EXPECT_EQ(encodeSrgb8(std::numeric_limits<float>::quiet_NaN()), 0);
    EXPECT_EQ(encodeUnorm8(std::numeric_limits<float>::quiet_NaN()), 0);
    EXPECT_EQ(encodeUnorm8(0.5f), 128);  // 127.5 rounds half up
    EXPECT_EQ(encodeUnorm8(1.5f), 255);
}

TEST(CaptureSrgb, FloatCurveIsTheInverseOfItself) {
    for (float v : {0.0f, 0.001f, 0.0031308f, 0.04045f, 0.2f, 0.5f, 0.99f, 1.0f}) {
        EXPECT_NEAR(srgbToLinear(linearToSrgb(v)), v, 1e-6f) << v;
    }
    EXPECT_NEAR(linearToSrgb(0.18f), 0.46135613f, 1e-6f);  // mid grey
}
