// SPDX-License-Identifier: MIT
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "engine/capture/compare.hpp"
#include "flat_image.hpp"

using namespace engine::capture;
using capture_test::flat;

TEST(CaptureCompare, IdenticalImagesHaveNoErrorAndPass) {
    const Image a = flat(4, 4, {0.2f, 0.4f, 0.6f});
    const CompareResult r = compareImages(a, a);
    EXPECT_EQ(r.meanError, 0.0);
    EXPECT_EQ(r.rmsError, 0.0);
    EXPECT_EQ(r.maxError, 0.0);
    EXPECT_TRUE(std::isinf(r.psnr));
    EXPECT_EQ(r.pixelsOverWarn, 0u);
    EXPECT_EQ(r.pixelsOverFail, 0u);
    EXPECT_EQ(r.pixelCount, 16u);
    EXPECT_EQ(r.verdict, Verdict::Pass);
    EXPECT_TRUE(r.mismatch.empty());
}

TEST(CaptureCompare, ConstantOffsetGivesKnownStatistics) {
    const Image a = flat(4, 4, {0.25f, 0.5f, 0.75f});
    const Image b = flat(4, 4, {0.375f, 0.625f, 0.875f});  // +0.125 everywhere, exactly
    const CompareResult r = compareImages(a, b);
    EXPECT_DOUBLE_EQ(r.meanError, 0.125);
    EXPECT_DOUBLE_EQ(r.rmsError, 0.125);
    EXPECT_DOUBLE_EQ(r.psnr, 20.0 * std::log10(1.0 / 0.125));  // peak 1: all values within [0,1]
    EXPECT_DOUBLE_EQ(r.maxError, 0.125);
    EXPECT_EQ(r.maxX, 0);  // the first value reaching the maximum, as idiff reports it
    EXPECT_EQ(r.maxY, 0);
    EXPECT_EQ(r.maxChannel, 0);
    EXPECT_EQ(r.pixelsOverFail, 16u);
    EXPECT_EQ(r.verdict, Verdict::Fail);

    CompareOptions loose;
    loose.failThreshold = 0.2f;
    loose.warnThreshold = 0.1f;
    EXPECT_EQ(compareImages(a, b, loose).verdict, Verdict::Warn);  // idiff 2.4.7 says PASS: see compare.hpp
    loose.warnThreshold = 0.2f;
    EXPECT_EQ(compareImages(a, b, loose).verdict, Verdict::Pass);
}

TEST(CaptureCompare, PsnrPeakIsTheLargestValueForHdrImages) {
    const Image a = flat(2, 2, {4.0f});
    const Image b = flat(2, 2, {3.5f});
    const CompareResult r = compareImages(a, b);
    EXPECT_DOUBLE_EQ(r.psnr, 20.0 * std::log10(4.0 / 0.5));
}

TEST(CaptureCompare, OnePixelDifferingIsFoundAndJudgedByPercentAndHardFail) {
    const Image a = flat(4, 4, {0.5f, 0.5f, 0.5f});
    Image b = a;
    b.at(2, 1, 1) = 0.0f;
    b.at(3, 3, 2) = 0.5f + 1e-7f;  // a difference under the 1e-6 thresholds: not a pixel over

    CompareOptions options;
    options.failPercent = 10.0f;  // 1 of 16 pixels = 6.25 %
    options.warnPercent = 10.0f;
    CompareResult r = compareImages(a, b, options);
    EXPECT_DOUBLE_EQ(r.maxError, 0.5);
    EXPECT_EQ(r.maxX, 2);
    EXPECT_EQ(r.maxY, 1);
    EXPECT_EQ(r.maxChannel, 1);
    EXPECT_EQ(r.pixelsOverFail, 1u);
    EXPECT_EQ(r.pixelsOverWarn, 1u);
    EXPECT_NEAR(r.meanError, 0.5 / 48.0, 1e-8);
    EXPECT_NEAR(r.rmsError, std::sqrt(0.25 / 48.0), 1e-8);
    EXPECT_EQ(r.verdict, Verdict::Pass);

    options.hardWarn = 0.25f;
    EXPECT_EQ(compareImages(a, b, options).verdict, Verdict::Warn);
    options.hardFail = 0.25f;
    EXPECT_EQ(compareImages(a, b, options).verdict, Verdict::Fail);
    options.failPercent = 5.0f;  // 6.25 % of pixels over: fails without a hard limit too
    options.hardFail = std::numeric_limits<float>::max();
    EXPECT_EQ(compareImages(a, b, options).verdict, Verdict::Fail);
}

TEST(CaptureCompare, SizeOrChannelMismatchIsAFailureNotACrash) {
    const Image a = flat(4, 4, {0.5f, 0.5f, 0.5f});
    const CompareResult size = compareImages(a, flat(4, 3, {0.5f, 0.5f, 0.5f}));
    EXPECT_EQ(size.verdict, Verdict::Fail);
    EXPECT_NE(size.mismatch.find("4x4x3 vs 4x3x3"), std::string::npos) << size.mismatch;
    const CompareResult channels = compareImages(a, flat(4, 4, {0.5f, 0.5f, 0.5f, 1.0f}));
    EXPECT_EQ(channels.verdict, Verdict::Fail);
    EXPECT_NE(channels.mismatch.find("4x4x3 vs 4x4x4"), std::string::npos) << channels.mismatch;
}

TEST(CaptureCompare, NanMatchesNanButNotANumber) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    Image a = flat(2, 1, {0.5f});
    a.at(0, 0, 0) = nan;
    Image b = a;
    EXPECT_EQ(compareImages(a, b).verdict, Verdict::Pass);

    b.at(0, 0, 0) = 0.5f;
    const CompareResult r = compareImages(a, b);
    EXPECT_TRUE(std::isinf(r.maxError));
    EXPECT_EQ(r.maxX, 0);
    EXPECT_EQ(r.pixelsOverFail, 1u);
    EXPECT_EQ(r.meanError, 0.0);  // non-finite pairs stay out of the averages
    EXPECT_EQ(r.verdict, Verdict::Fail);
}
