// SPDX-License-Identifier: MIT
// Mip chains: sizes, premultiplied filtering (no colour bleeding from transparent texels,
// [Hargreaves 2009]), and Castaño's coverage preservation for alpha-tested foliage: coverage at the
// cutoff stays at level 0's down the chain, while plain box filtering loses it.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "assets_test_util.hpp"
#include "engine/assets/mips.hpp"

namespace {

using namespace engine::assets;
using engine::render::AlphaMode;

// Foliage-like alpha: small leaves (discs of radius 1.5..3.5 texels with a soft one-texel
// edge) scattered over a transparent background, from a fixed xorshift sequence so the test
// is the same everywhere. Leaves this small become sub-texel a few levels down, which is
// where box filtering makes alpha-tested foliage go bald.
RgbaImage scatteredLeaves(int size, int leaves) {
    RgbaImage image = RgbaImage::make(size, size);
    std::uint32_t state = 0x9E3779B9u;
    const auto next = [&] {
        state ^= state << 13;
        state ^= state >> 17;
        state ^= state << 5;
        return static_cast<float>(state % 100000u) / 100000.0f;
    };
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            std::uint8_t* t = image.texel(x, y);
            t[0] = 50;
            t[1] = 150;
            t[2] = 40;
        }
    for (int i = 0; i < leaves; ++i) {
        const float cx = next() * static_cast<float>(size);
        const float cy = next() * static_cast<float>(size);
        const float radius = 1.5f + 2.0f * next();
        for (int y = static_cast<int>(cy - radius - 1); y <= static_cast<int>(cy + radius + 1); ++y)
            for (int x = static_cast<int>(cx - radius - 1); x <= static_cast<int>(cx + radius + 1); ++x) {
                if (x < 0 || y < 0 || x >= size || y >= size) continue;
                const float d = std::hypot(static_cast<float>(x) + 0.5f - cx, static_cast<float>(y) + 0.5f - cy);
                const float a = std::clamp(radius - d, 0.0f, 1.0f);
                std::uint8_t* t = image.texel(x, y);
                t[3] = std::max(t[3], static_cast<std::uint8_t>(std::lround(a * 255.0f)));
            }
    }
    return image;
}

TEST(Mips, ChainSizesGoDownToOneByOne) {
    const auto square = generateMips(RgbaImage::make(256, 256));
    ASSERT_EQ(square.size(), 9u);
    EXPECT_EQ(square.back().width, 1);
    EXPECT_EQ(square.back().height, 1);
    const auto wide = generateMips(RgbaImage::make(8, 2));
    ASSERT_EQ(wide.size(), 4u);
    EXPECT_EQ(wide[1].width, 4);
    EXPECT_EQ(wide[1].height, 1);
    EXPECT_EQ(wide[3].width, 1);
    MipOptions options;
    options.maxLevels = 3;
    EXPECT_EQ(generateMips(RgbaImage::make(64, 64), options).size(), 3u);
    EXPECT_EQ(engine::assets::textureData(square).levels.size(), 9u);
    EXPECT_EQ(engine::assets::textureData(square).levels[1].size(), 128u * 128u * 4u);
}

TEST(Mips, FilteringIsPremultipliedSoTransparentColourDoesNotBleed) {
    // Left column opaque red, right column transparent with straight colour green.
    RgbaImage image = RgbaImage::make(2, 2);
    for (int y = 0; y < 2; ++y) {
        std::uint8_t* red = image.texel(0, y);
        red[0] = 255;
        red[3] = 255;
        std::uint8_t* green = image.texel(1, y);
        green[1] = 255;
        green[3] = 0;
    }
    MipOptions straight;
    straight.output = AlphaMode::Straight;
    const auto levels = generateMips(image, straight);
    ASSERT_EQ(levels.size(), 2u);
    const std::uint8_t* mixed = levels[1].texel(0, 0);
    EXPECT_EQ(mixed[0], 255);  // straight colour is the opaque texels' colour only
    EXPECT_EQ(mixed[1], 0);
    EXPECT_EQ(mixed[3], 128);

    const auto premultiplied = generateMips(image);
    EXPECT_EQ(premultiplied[0].alpha, AlphaMode::Premultiplied);
    EXPECT_EQ(premultiplied[0].texel(1, 0)[1], 0);  // alpha 0: premultiplied colour is 0
    const std::uint8_t* p = premultiplied[1].texel(0, 0);
    EXPECT_EQ(p[0], 188);  // sRGB code of linear 0.5 (filtering happens in linear light)
    EXPECT_EQ(p[1], 0);
    EXPECT_EQ(p[3], 128);
}

TEST(Mips, CoverageIsPreservedWhereBoxFilteringLosesIt) {
    const RgbaImage leaves = scatteredLeaves(256, 1500);
    const float cutoff = 0.5f;
    const float coverage0 = alphaCoverage(leaves, cutoff);
    ASSERT_GT(coverage0, 0.2f);
    ASSERT_LT(coverage0, 0.5f);

    const auto plain = generateMips(leaves);
    const auto preserved = generateCoveragePreservingMips(leaves, cutoff);
    ASSERT_EQ(plain.size(), preserved.size());
    for (std::size_t level = 1; level < preserved.size(); ++level) {
        const RgbaImage& image = preserved[level];
        // Coverage can only move in steps of one texel; allow one step plus 1%.
        const float tolerance = 0.01f + 1.0f / static_cast<float>(image.pixelCount());
        EXPECT_NEAR(alphaCoverage(image, cutoff), coverage0, tolerance)
            << "level " << level << " (" << image.width << "x" << image.height << ")";
    }
    // Box filtering averages sub-texel leaves with the background: at 16x16 (level 4) less than
    // a quarter of the coverage is left, at 4x4 none (measured: 0.27 -> 0.016 -> 0).
    EXPECT_LT(alphaCoverage(plain[4], cutoff), coverage0 * 0.25f);
    EXPECT_LT(alphaCoverage(plain[6], cutoff), 0.01f);
}

TEST(Mips, CoveragePreservationWorksForStraightOutputToo) {
    const RgbaImage leaves = scatteredLeaves(64, 100);
    const auto levels = generateCoveragePreservingMips(leaves, 0.5f, AlphaMode::Straight);
    EXPECT_EQ(levels[2].alpha, AlphaMode::Straight);
    EXPECT_NEAR(alphaCoverage(levels[2], 0.5f), alphaCoverage(leaves, 0.5f), 0.01f + 1.0f / 256.0f);
    // Straight colour of covered texels stays the leaf colour.
    for (int y = 0; y < levels[2].height; ++y)
        for (int x = 0; x < levels[2].width; ++x)
            if (levels[2].texel(x, y)[3] > 0) {
                EXPECT_NEAR(levels[2].texel(x, y)[1], 150, 1);
            }
}

TEST(Mips, BadArgumentsAreRefused) {
    EXPECT_THROW(generateCoveragePreservingMips(RgbaImage::make(4, 4), 0.0f), engine::Error);
    EXPECT_THROW(generateCoveragePreservingMips(RgbaImage::make(4, 4), 1.5f), engine::Error);
    EXPECT_THROW(generateMips(RgbaImage{}), engine::Error);
}

}  // namespace
