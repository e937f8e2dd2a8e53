// SPDX-License-Identifier: MIT
// Reading the texture formats we do not write ourselves (TGA, JPEG, 16-bit and linear PNG);
// fixtures are made with OpenImageIO directly.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <cstdint>
#include <vector>

#include "engine/capture/image_read.hpp"
#include "engine/capture/image_write.hpp"
#include "engine/capture/srgb.hpp"
#include "engine/core/error.hpp"
#include "temp_dir.hpp"

using namespace engine::capture;

namespace {

// Writes raw values with OpenImageIO, telling it they are straight so it stores them as given.
template <typename T>
void writeRaw(const std::filesystem::path& path, int width, int height, int channels, OIIO::TypeDesc type,
              const std::vector<T>& values, const char* colorSpace = nullptr) {
    OIIO::ImageSpec spec(width, height, channels, type);
    spec.attribute("oiio:UnassociatedAlpha", 1);
    if (colorSpace) spec.attribute("oiio:ColorSpace", colorSpace);
    auto out = OIIO::ImageOutput::create(path.string());
    ASSERT_TRUE(out) << OIIO::geterror();
    ASSERT_TRUE(out->open(path.string(), spec)) << out->geterror();
    ASSERT_TRUE(out->write_image(type, values.data())) << out->geterror();
    ASSERT_TRUE(out->close());
}

}  // namespace

TEST(CaptureTextureRead, TgaAlphaStaysStraight) {
    ssam::testing::TempDir dir;
    const std::vector<std::uint8_t> rgba = {200, 100, 50, 0, 10, 20, 30, 255};
    writeRaw(dir / "straight.tga", 2, 1, 4, OIIO::TypeDesc::UINT8, rgba);
    const Image8 codes = readImage8(dir / "straight.tga");
    EXPECT_EQ(codes.alpha, AlphaMode::Straight);
    EXPECT_EQ(codes.pixels, rgba);
    const Image linear = readImage(dir / "straight.tga");
    EXPECT_EQ(linear.at(0, 0, 0), decodeSrgb8(200));  // colour kept under alpha 0
}

TEST(CaptureTextureRead, JpegIsStraightSrgbColour) {
    ssam::testing::TempDir dir;
    const std::vector<std::uint8_t> grey(8 * 8 * 3, 128);
    writeRaw(dir / "grey.jpg", 8, 8, 3, OIIO::TypeDesc::UINT8, grey);
    const Image image = readImage(dir / "grey.jpg");
    EXPECT_EQ(image.channels, 3);
    EXPECT_EQ(image.alpha, AlphaMode::Straight);
    EXPECT_NEAR(image.at(3, 3, 1), decodeSrgb8(128), 0.01f);  // lossy, but a flat grey survives
}

TEST(CaptureTextureRead, SixteenBitPngIsDecodedWithTheFloatCurve) {
    ssam::testing::TempDir dir;
    const std::vector<std::uint16_t> values = {0, 32768, 65535};
    writeRaw(dir / "sixteen.png", 1, 1, 3, OIIO::TypeDesc::UINT16, values);
    const Image image = readImage(dir / "sixteen.png");
    EXPECT_EQ(image.at(0, 0, 0), 0.0f);
    EXPECT_NEAR(image.at(0, 0, 1), srgbToLinear(32768.0f / 65535.0f), 1e-6f);
    EXPECT_FLOAT_EQ(image.at(0, 0, 2), 1.0f);
    EXPECT_THROW(readImage8(dir / "sixteen.png"), engine::Error);  // not 8-bit codes
}

TEST(CaptureTextureRead, PngMarkedLinearIsNotDecoded) {
    ssam::testing::TempDir dir;
    const std::vector<std::uint8_t> values = {51, 102, 204};
    writeRaw(dir / "linear.png", 1, 1, 3, OIIO::TypeDesc::UINT8, values, "linear");
    const Image image = readImage(dir / "linear.png");
    EXPECT_EQ(image.at(0, 0, 0), 51.0f / 255.0f);
    EXPECT_EQ(image.at(0, 0, 2), 204.0f / 255.0f);
}

TEST(CaptureTextureRead, ExrIsLinearAndPremultiplied) {
    ssam::testing::TempDir dir;
    Image image = Image::make(3, 2, 4);
    image.fill({0.25f, 2.5f, -0.125f, 0.5f});
    writeExr(dir / "plain.exr", image, ExrPixelType::Half);
    const Image back = readImage(dir / "plain.exr");
    EXPECT_EQ(back.alpha, AlphaMode::Premultiplied);
    EXPECT_EQ(back.channelNames, image.channelNames);
    EXPECT_EQ(back.pixels, image.pixels);  // all exactly representable in half
}
