// SPDX-License-Identifier: MIT
// RMSE/PSNR, SSIM and temporal flicker (engine/capture/metrics.hpp). ꟻLIP is in flip_test.cpp.
#include <gtest/gtest.h>

#include <tbb/global_control.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "engine/capture/metrics.hpp"
#include "engine/capture/srgb.hpp"
#include "engine/core/error.hpp"
#include "flat_image.hpp"

using namespace engine::capture;
using capture_test::flat;

namespace {

// A smooth colour gradient with some structure, RGB in [0,1] linear.
Image pattern(int width, int height) {
    Image image = Image::make(width, height, 4);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            image.at(x, y, 0) = 0.5f + 0.4f * std::sin(0.21f * static_cast<float>(x));
            image.at(x, y, 1) = static_cast<float>(y) / static_cast<float>(height);
            image.at(x, y, 2) = ((x / 8 + y / 8) % 2) ? 0.8f : 0.1f;
            image.at(x, y, 3) = 1.0f;
        }
    return image;
}

// `image` plus Gaussian noise of standard deviation `sigma` on the colour channels (fixed seed).
Image noisy(const Image& image, float sigma, unsigned seed = 1234) {
    std::mt19937 rng(seed);
    std::normal_distribution<float> noise(0.0f, 1.0f);
    Image out = image;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            for (int c = 0; c < 3; ++c) out.at(x, y, c) += sigma * noise(rng);
    return out;
}

double srgb(double linear) {
    return linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}

}  // namespace

// ---- RMSE / PSNR ----

TEST(CaptureMetrics, IdenticalImagesHaveZeroRmseAndInfinitePsnr) {
    const Image a = pattern(32, 24);
    EXPECT_EQ(rmseLinear(a, a), 0.0);
    EXPECT_EQ(rmseSrgb(a, a), 0.0);
    EXPECT_TRUE(std::isinf(psnrLinear(a, a)) && psnrLinear(a, a) > 0);
    EXPECT_TRUE(std::isinf(psnrSrgb(a, a)) && psnrSrgb(a, a) > 0);
}

TEST(CaptureMetrics, ConstantLinearOffsetGivesKnownRmseAndPsnr) {
    const Image a = flat(5, 3, {0.25f, 0.5f, 0.75f, 1.0f});
    const Image b = flat(5, 3, {0.375f, 0.625f, 0.875f, 0.0f});  // +0.125 exactly; alpha differs and is ignored
    EXPECT_DOUBLE_EQ(rmseLinear(a, b), 0.125);
    EXPECT_DOUBLE_EQ(psnrLinear(a, b), 20.0 * std::log10(8.0));  // 18.0618 dB
    EXPECT_NEAR(psnrLinear(a, b), 18.0618, 1e-4);
}

TEST(CaptureMetrics, OffsetInOneChannelIsAveragedOverThreeChannels) {
    const Image a = flat(4, 4, {0.5f, 0.5f, 0.5f});
    const Image b = flat(4, 4, {0.5f, 0.5f, 0.25f});
    EXPECT_DOUBLE_EQ(rmseLinear(a, b), std::sqrt(0.25 * 0.25 / 3.0));
}

TEST(CaptureMetrics, SrgbRmseEncodesWithTheExactCurveAfterClamping) {
    EXPECT_DOUBLE_EQ(rmseSrgb(flat(3, 3, {0, 0, 0}), flat(3, 3, {1, 1, 1})), 1.0);
    EXPECT_DOUBLE_EQ(psnrSrgb(flat(3, 3, {0, 0, 0}), flat(3, 3, {1, 1, 1})), 0.0);
    // Linear 0.5 encodes to 0.735357; against black, every value differs by that much.
    EXPECT_NEAR(rmseSrgb(flat(3, 3, {0.5f, 0.5f, 0.5f}), flat(3, 3, {0, 0, 0})), srgb(0.5), 1e-6);
    EXPECT_NEAR(srgb(0.5), 0.735357, 1e-6);
    // Above 1 clamps: no sRGB difference, though the linear one is 1.
    EXPECT_EQ(rmseSrgb(flat(3, 3, {2, 2, 2}), flat(3, 3, {1, 1, 1})), 0.0);
    EXPECT_DOUBLE_EQ(rmseLinear(flat(3, 3, {2, 2, 2}), flat(3, 3, {1, 1, 1})), 1.0);
    // Negative values clamp to 0.
    EXPECT_EQ(rmseSrgb(flat(3, 3, {-1, 0, -0.5f}), flat(3, 3, {0, 0, 0})), 0.0);
}

TEST(CaptureMetrics, SrgbRmseAgreesWithLinearToSrgb) {
    // The metrics evaluate the curve in float; linearToSrgb evaluates it in double.
    const Image a = noisy(pattern(48, 32), 0.2f, 5);
    const Image b = noisy(pattern(48, 32), 0.2f, 6);
    double sum = 0.0;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x)
            for (int c = 0; c < 3; ++c) {
                const double d = static_cast<double>(linearToSrgb(std::clamp(a.at(x, y, c), 0.0f, 1.0f))) -
                                 static_cast<double>(linearToSrgb(std::clamp(b.at(x, y, c), 0.0f, 1.0f)));
                sum += d * d;
            }
    EXPECT_NEAR(rmseSrgb(a, b), std::sqrt(sum / (48.0 * 32.0 * 3.0)), 1e-6);
}

TEST(CaptureMetrics, ColourChannelsAreFoundByNameAndAlphaIsIgnored) {
    Image a = Image::make(2, 2, {"A", "B", "G", "R"});
    Image b = Image::make(2, 2, {"A", "B", "G", "R"});
    a.fill({1.0f, 0.0f, 0.0f, 0.5f});
    b.fill({0.0f, 0.0f, 0.0f, 0.5f});  // only alpha differs
    EXPECT_EQ(rmseLinear(a, b), 0.0);
    b.fill({1.0f, 0.0f, 0.0f, 0.0f});  // R differs by 0.5
    EXPECT_DOUBLE_EQ(rmseLinear(a, b), std::sqrt(0.25 / 3.0));
}

TEST(CaptureMetrics, MismatchedImagesThrow) {
    const Image a = pattern(16, 16);
    const Image wider = pattern(17, 16);
    const Image rgb = flat(16, 16, {0, 0, 0});  // 3 channels vs 4
    const Image gray = flat(16, 16, {0.5f});
    for (const Image* other : {&wider, &rgb}) {
        EXPECT_THROW(rmseLinear(a, *other), engine::Error);
        EXPECT_THROW(psnrLinear(a, *other), engine::Error);
        EXPECT_THROW(rmseSrgb(a, *other), engine::Error);
        EXPECT_THROW(psnrSrgb(a, *other), engine::Error);
        EXPECT_THROW(ssim(a, *other), engine::Error);
        EXPECT_THROW(flip(a, *other), engine::Error);
        EXPECT_THROW(temporalFlicker({a, *other}), engine::Error);
    }
    EXPECT_THROW(rmseLinear(gray, gray), engine::Error);  // no RGB
    EXPECT_THROW(flip(gray, gray), engine::Error);
    EXPECT_THROW(rmseLinear(Image{}, Image{}), engine::Error);
    try {
        rmseLinear(a, wider);
        FAIL();
    } catch (const engine::Error& e) {
        EXPECT_NE(std::string(e.what()).find("16x16x4 vs 17x16x4"), std::string::npos) << e.what();
    }
}

// ---- SSIM ----

TEST(CaptureMetrics, SsimOfIdenticalImagesIsExactlyOne) {
    const Image a = noisy(pattern(40, 30), 0.1f);
    EXPECT_EQ(ssim(a, a), 1.0);
}

TEST(CaptureMetrics, SsimDecreasesMonotonicallyWithNoise) {
    const Image a = pattern(64, 48);
    double previous = 1.0;
    for (const float sigma : {0.002f, 0.01f, 0.03f, 0.1f, 0.3f}) {
        const double s = ssim(a, noisy(a, sigma));
        EXPECT_LT(s, previous) << "sigma " << sigma;
        EXPECT_GT(s, -1.0);
        previous = s;
    }
    EXPECT_LT(previous, 0.5);  // heavy noise destroys most structure
}

TEST(CaptureMetrics, SsimOfFlatImagesIsTheLuminanceTerm) {
    // Zero variance everywhere: SSIM = (2 mu_a mu_b + C1) / (mu_a^2 + mu_b^2 + C1).
    const double c1 = 1e-4;
    EXPECT_NEAR(ssim(flat(12, 12, {0, 0, 0}), flat(12, 12, {1, 1, 1})), c1 / (1.0 + c1), 1e-12);
    const double mu = srgb(0.2);  // luma of a grey equals its encoded value (weights sum to 1)
    EXPECT_NEAR(ssim(flat(12, 12, {0.2f, 0.2f, 0.2f}), flat(12, 12, {1, 1, 1})), (2.0 * mu + c1) / (mu * mu + 1.0 + c1),
                1e-6);
}

TEST(CaptureMetrics, SsimIsSymmetricAndRejectsImagesSmallerThanTheWindow) {
    const Image a = pattern(30, 20);
    const Image b = noisy(a, 0.05f);
    EXPECT_EQ(ssim(a, b), ssim(b, a));
    EXPECT_NO_THROW(ssim(flat(11, 11, {0, 0, 0}), flat(11, 11, {0, 0, 0})));
    EXPECT_THROW(ssim(flat(10, 11, {0, 0, 0}), flat(10, 11, {0, 0, 0})), engine::Error);
    EXPECT_THROW(ssim(flat(11, 10, {0, 0, 0}), flat(11, 10, {0, 0, 0})), engine::Error);
}

// ---- Temporal flicker ----

TEST(CaptureMetrics, FlickerOfAConstantSequenceIsZero) {
    const Image a = pattern(20, 10);
    EXPECT_EQ(temporalFlicker({a, a, a, a}), 0.0);
}

TEST(CaptureMetrics, FlickerOfAlternatingBlackAndWhiteIsOne) {
    const Image black = flat(1, 1, {0, 0, 0});
    const Image white = flat(1, 1,
                             {
                                 1,
                                 1,
                                 1,
                             });
    EXPECT_DOUBLE_EQ(temporalFlicker({black, white, black, white, black}), 1.0);
    EXPECT_DOUBLE_EQ(temporalFlicker({black, white}), 1.0);
}

TEST(CaptureMetrics, FlickerAveragesOverPairsAndPixels) {
    // 2 pixels, 3 frames: pixel 0 steps 0 -> encoded 0.5 -> 0.5, pixel 1 is static.
    const float half = srgbToLinear(0.5f);
    Image f0 = flat(2, 1, {0, 0, 0});
    Image f1 = f0, f2 = f0;
    for (Image* f : {&f1, &f2})
        for (int c = 0; c < 3; ++c) f->at(0, 0, c) = half;
    EXPECT_NEAR(temporalFlicker({f0, f1, f2}), 0.5 / 4.0, 1e-6);  // one change of 0.5 over 2 pixels x 2 pairs
}

TEST(CaptureMetrics, FlickerNeedsTwoMatchingFrames) {
    EXPECT_THROW(temporalFlicker({}), engine::Error);
    EXPECT_THROW(temporalFlicker({flat(2, 2, {0, 0, 0})}), engine::Error);
    EXPECT_THROW(temporalFlicker({flat(2, 2, {0, 0, 0}), flat(2, 2, {0, 0, 0}), flat(2, 3, {0, 0, 0})}), engine::Error);
}

// ---- Determinism ----

TEST(CaptureMetrics, ResultsDoNotDependOnTheThreadCount) {
    const Image a = pattern(97, 61);
    const Image b = noisy(a, 0.05f);
    auto all = [&] {
        return std::vector<double>{rmseLinear(a, b), rmseSrgb(a, b), ssim(a, b), flip(a, b),
                                   temporalFlicker({a, b, a})};
    };
    std::vector<double> serial;
    {
        tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
        serial = all();
    }
    const std::vector<double> parallel = all();
    ASSERT_EQ(serial.size(), parallel.size());
    for (std::size_t i = 0; i < serial.size(); ++i) EXPECT_EQ(serial[i], parallel[i]) << "metric " << i;
    EXPECT_EQ(all(), parallel);
}

TEST(CaptureMetrics, NaNInputGivesNaN) {
    const Image a = pattern(24, 24);
    Image b = a;
    b.at(12, 12, 1) = std::numeric_limits<float>::quiet_NaN();
    EXPECT_TRUE(std::isnan(rmseLinear(a, b)));
    EXPECT_TRUE(std::isnan(rmseSrgb(a, b)));
    EXPECT_TRUE(std::isnan(psnrSrgb(a, b)));
    EXPECT_TRUE(std::isnan(ssim(a, b)));
    EXPECT_TRUE(std::isnan(flip(a, b)));
    EXPECT_TRUE(std::isnan(temporalFlicker({a, b})));
}
