// SPDX-License-Identifier: MIT
#include <gtest/gtest.h>

#include <limits>

#include "engine/capture/image_convert.hpp"
#include "engine/capture/image_read.hpp"
#include "engine/capture/image_write.hpp"
#include "engine/capture/srgb.hpp"
#include "engine/core/error.hpp"
#include "temp_dir.hpp"

using namespace engine::capture;

namespace {
// Every code 0..255 appears in every channel, at different places per channel.
Image8 allCodesImage(int channels) {
    Image8 image = Image8::make(16, 16, channels);
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x)
            for (int c = 0; c < channels; ++c)
                image.at(x, y, c) = static_cast<std::uint8_t>((y * 16 + x + c * 37) % 256);
    return image;
}
}  // namespace

TEST(CapturePng, EightBitRoundTripIsExactForEveryChannelCount) {
    ssam::testing::TempDir dir;
    for (int channels = 1; channels <= 4; ++channels) {
        const Image8 written = allCodesImage(channels);
        const auto path = dir / ("codes" + std::to_string(channels) + ".png");
        writePng(path, written);
        const Image8 read = readImage8(path);
        EXPECT_EQ(read.width, 16);
        EXPECT_EQ(read.height, 16);
        EXPECT_EQ(read.channels, channels);
        EXPECT_EQ(read.alpha, AlphaMode::Straight);
        EXPECT_EQ(read.pixels, written.pixels) << channels << " channels";
    }
}

TEST(CapturePng, StraightAlphaKeepsColourWhereAlphaIsZero) {
    ssam::testing::TempDir dir;
    Image8 written = Image8::make(2, 1, 4);
    written.fill({200, 100, 50, 0});  // invisible, but its colour matters (e.g. for filtering)
    written.at(1, 0, 3) = 128;
    const auto path = dir / "alpha.png";
    writePng(path, written);

    const Image8 codes = readImage8(path);
    EXPECT_EQ(codes.pixels, written.pixels);  // OpenImageIO neither premultiplied on read nor divided on write

    const Image linear = readImage(path);
    EXPECT_EQ(linear.alpha, AlphaMode::Straight);
    EXPECT_EQ(linear.at(0, 0, 0), decodeSrgb8(200));
    EXPECT_EQ(linear.at(0, 0, 3), 0.0f);
    EXPECT_EQ(linear.at(1, 0, 1), decodeSrgb8(100));
    EXPECT_EQ(linear.at(1, 0, 3), 128.0f / 255.0f);
}

TEST(CapturePng, FloatImageIsWrittenAsExactSrgbCodesAndReadBackLinear) {
    ssam::testing::TempDir dir;
    Image image = Image::make(256, 1, 3, AlphaMode::Straight);
    for (int x = 0; x < 256; ++x) image.at(x, 0, 0) = decodeSrgb8(static_cast<std::uint8_t>(x));
    image.at(0, 0, 1) = std::numeric_limits<float>::quiet_NaN();
    image.at(1, 0, 1) = -1.0f;
    image.at(2, 0, 1) = 4.0f;
    const auto path = dir / "ramp.png";
    writePng(path, image);

    const Image8 codes = readImage8(path);
    for (int x = 0; x < 256; ++x) EXPECT_EQ(codes.at(x, 0, 0), x);
    EXPECT_EQ(codes.at(0, 0, 1), 0);    // NaN
    EXPECT_EQ(codes.at(1, 0, 1), 0);    // clamped
    EXPECT_EQ(codes.at(2, 0, 1), 255);  // clamped

    const Image back = readImage(path);
    for (int x = 0; x < 256; ++x) EXPECT_EQ(back.at(x, 0, 0), image.at(x, 0, 0));
}

TEST(CapturePng, PremultipliedImageIsStoredStraight) {
    ssam::testing::TempDir dir;
    Image image = Image::make(1, 1, 4, AlphaMode::Premultiplied);
    image.fill({0.25f, 0.1f, 0.0f, 0.5f});
    const auto path = dir / "premultiplied.png";
    writePng(path, image);
    const Image8 codes = readImage8(path);
    EXPECT_EQ(codes.at(0, 0, 0), encodeSrgb8(0.5f));
    EXPECT_EQ(codes.at(0, 0, 1), encodeSrgb8(0.2f));
    EXPECT_EQ(codes.at(0, 0, 3), 128);
}

TEST(CapturePng, StoredValuesCanBeReadWithoutLinearising) {
    ssam::testing::TempDir dir;
    Image8 written = Image8::make(1, 1, 3);
    written.fill({51, 102, 255});
    const auto path = dir / "stored.png";
    writePng(path, written);
    ReadOptions options;
    options.linearize = false;
    const Image stored = readImage(path, options);
    EXPECT_EQ(stored.at(0, 0, 0), 51.0f / 255.0f);
    EXPECT_EQ(stored.at(0, 0, 2), 1.0f);
}

TEST(CapturePng, LayoutsPngCannotHoldAreRefused) {
    ssam::testing::TempDir dir;
    EXPECT_THROW(writePng(dir / "five.png", Image::make(2, 2, 5)), engine::Error);
    EXPECT_THROW(writePng(dir / "rgbz.png", Image::make(2, 2, {"R", "G", "B", "Z"})), engine::Error);
    Image8 premultiplied = Image8::make(2, 2, 4, AlphaMode::Premultiplied);
    EXPECT_THROW(writePng(dir / "premultiplied8.png", premultiplied), engine::Error);
}
