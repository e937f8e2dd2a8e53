// SPDX-License-Identifier: MIT
// LDR-ꟻLIP (engine/capture/metrics.hpp, engine/capture/src/metrics_flip.cpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "engine/capture/metrics.hpp"
#include "engine/core/error.hpp"
#include "flat_image.hpp"

using namespace engine::capture;
using capture_test::flat;

namespace {

Image randomImage(int width, int height, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    Image image = Image::make(width, height, 3);
    for (float& v : image.pixels) v = u(rng);
    return image;
}

// Hand computation (paper equations) for two flat images, where filtering changes nothing and
// there are no features: the remapped HyAB distance of the Hunt-adjusted L*a*b* colours.
// Green (0,1,0) -> L*a*b* (87.7347, -86.1827, 83.1793), Hunt-adjusted a*,b* = (-75.6122, 72.9771);
// blue (0,0,1) -> (32.2970, 79.1875, -107.8602), Hunt-adjusted (25.5752, -34.8356);
// HyAB = 55.4377 + 147.8596 = 203.2973, cmax = 203.2973^0.7 = 41.2755.
constexpr double kCmax = 41.27548;
double remap(double hyab) {
    const double e = std::pow(hyab, 0.7);
    return e < 0.4 * kCmax ? 0.95 / (0.4 * kCmax) * e : 0.95 + (e - 0.4 * kCmax) / (0.6 * kCmax) * 0.05;
}

}  // namespace

TEST(CaptureFlip, DefaultPixelsPerDegreeIsTheSeventyCentimetreSetup) {
    EXPECT_NEAR(FlipOptions{}.pixelsPerDegree, 67.0206, 1e-4);  // 3840 * pi / 180
    EXPECT_DOUBLE_EQ(flipPixelsPerDegree(0.7, 3840.0, 0.7), 3840.0 * 3.14159265358979323846 / 180.0);
}

TEST(CaptureFlip, IdenticalImagesGiveZero) {
    const Image a = randomImage(50, 40, 1);
    Image map;
    EXPECT_EQ(flip(a, a, {}, &map), 0.0);
    ASSERT_EQ(map.width, 50);
    ASSERT_EQ(map.height, 40);
    ASSERT_EQ(map.channels, 1);
    EXPECT_TRUE(std::all_of(map.pixels.begin(), map.pixels.end(), [](float v) { return v == 0.0f; }));
}

TEST(CaptureFlip, BlackVersusWhiteIsCloseToOne) {
    // L* 0 vs 100: HyAB 100 -> 100^0.7 = 25.12 > 0.4 cmax -> 0.95 + (25.12 - 16.51) / 24.77 * 0.05 = 0.9674.
    const double value = flip(flat(32, 32, {0, 0, 0}), flat(32, 32, {1, 1, 1}));
    EXPECT_NEAR(value, remap(100.0), 1e-4);
    EXPECT_NEAR(value, 0.9674, 1e-4);
}

TEST(CaptureFlip, FlatGreyDifferenceMatchesTheHandComputation) {
    // Linear grey 0.5 -> L* 76.0693, 0.6 -> L* 81.8382 (a*, b* = 0 for greys): HyAB = 5.7689.
    const double value = flip(flat(24, 24, {0.5f, 0.5f, 0.5f}), flat(24, 24, {0.6f, 0.6f, 0.6f}));
    EXPECT_NEAR(value, remap(81.83817 - 76.06926), 1e-4);
    EXPECT_NEAR(value, 0.19622, 1e-4);
}

TEST(CaptureFlip, LargerColourDifferenceGivesLargerError) {
    const Image base = flat(32, 32, {0.3f, 0.4f, 0.5f});
    double previous = 0.0;
    for (const float offset : {0.001f, 0.01f, 0.05f, 0.1f, 0.3f, 0.5f}) {
        const double value = flip(base, flat(32, 32, {0.3f + offset, 0.4f, 0.5f - offset * 0.5f}));
        EXPECT_GT(value, previous) << "offset " << offset;
        previous = value;
    }
}

TEST(CaptureFlip, ResultAndMapStayInUnitRangeAndTheMeanMatchesTheMap) {
    const Image a = randomImage(64, 48, 2);
    const Image b = randomImage(64, 48, 3);
    Image map;
    const double value = flip(a, b, {}, &map);
    EXPECT_GT(value, 0.0);
    EXPECT_LE(value, 1.0);
    double sum = 0.0;
    for (const float v : map.pixels) {
        EXPECT_GE(v, 0.0f);
        EXPECT_LE(v, 1.0f);
        sum += v;
    }
    EXPECT_NEAR(sum / static_cast<double>(map.pixels.size()), value, 1e-9);
}

TEST(CaptureFlip, IsSymmetricInItsArguments) {
    // Every step of the pipeline treats both images alike, so swapping them changes nothing.
    const Image a = randomImage(40, 30, 4);
    const Image b = randomImage(40, 30, 5);
    EXPECT_EQ(flip(a, b), flip(b, a));
}

TEST(CaptureFlip, ErrorStaysNearADifference) {
    // A one-pixel vertical line on grey: error only within the filter reach of the line
    // (CSF radius 10 px at 67 PPD).
    const Image a = flat(64, 16, {0.5f, 0.5f, 0.5f});
    Image b = a;
    for (int y = 0; y < 16; ++y)
        for (int c = 0; c < 3; ++c) b.at(32, y, c) = 0.9f;
    Image map;
    EXPECT_GT(flip(a, b, {}, &map), 0.0);
    EXPECT_GT(map.at(32, 8, 0), 0.05f);
    for (int x = 0; x < 64; ++x)
        if (std::abs(x - 32) > 10) {
            EXPECT_EQ(map.at(x, 8, 0), 0.0f) << "x " << x;
        }
}

TEST(CaptureFlip, FineDetailMattersMoreAtFewerPixelsPerDegree) {
    // A 1-pixel checkerboard vs its mean grey: at 67 PPD the CSFs blur it nearly away; seen
    // closer (fewer pixels per degree) the difference is plainly visible.
    Image checker = Image::make(32, 32, 3);
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 32; ++x)
            for (int c = 0; c < 3; ++c) checker.at(x, y, c) = ((x + y) % 2) ? 1.0f : 0.0f;
    const Image grey = flat(32, 32, {0.5f, 0.5f, 0.5f});
    const double far = flip(checker, grey);
    const double near = flip(checker, grey, {.pixelsPerDegree = 10.0});
    EXPECT_LT(far, near);
}

TEST(CaptureFlip, RejectsBadPixelsPerDegree) {
    const Image a = flat(8, 8, {0, 0, 0});
    EXPECT_THROW(flip(a, a, {.pixelsPerDegree = 0.0}), engine::Error);
    EXPECT_THROW(flip(a, a, {.pixelsPerDegree = -5.0}), engine::Error);
}
