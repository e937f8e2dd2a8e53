// SPDX-License-Identifier: MIT
#include <gtest/gtest.h>

#include "engine/capture/image.hpp"
#include "engine/capture/image_convert.hpp"
#include "engine/core/error.hpp"

using namespace engine::capture;

TEST(CaptureImage, MakeGivesZerosWithDefaultChannelNames) {
    const Image image = Image::make(3, 2, 4);
    EXPECT_EQ(image.width, 3);
    EXPECT_EQ(image.height, 2);
    EXPECT_EQ(image.channels, 4);
    EXPECT_EQ(image.channelNames, (std::vector<std::string>{"R", "G", "B", "A"}));
    EXPECT_EQ(image.pixels.size(), 24u);
    EXPECT_EQ(image.alphaChannel(), 3);
    for (float v : image.pixels) EXPECT_EQ(v, 0.0f);
}

TEST(CaptureImage, AtAddressesInterleavedRowsTopDown) {
    Image image = Image::make(4, 3, 2);
    image.at(3, 2, 1) = 7.0f;
    EXPECT_EQ(image.pixels[(2 * 4 + 3) * 2 + 1], 7.0f);
    EXPECT_EQ(image.at(3, 2, 1), 7.0f);
}

TEST(CaptureImage, FillSetsEveryPixelAndChecksTheChannelCount) {
    Image image = Image::make(2, 2, 3);
    image.fill({0.25f, 0.5f, 1.0f});
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 2; ++x) {
            EXPECT_EQ(image.at(x, y, 0), 0.25f);
            EXPECT_EQ(image.at(x, y, 2), 1.0f);
        }
    EXPECT_THROW(image.fill({1.0f, 2.0f}), engine::Error);
}

TEST(CaptureImage, ZeroSizeIsAnError) {
    EXPECT_THROW(Image::make(0, 4, 3), engine::Error);
    EXPECT_THROW(Image::make(4, 4, 0), engine::Error);
    EXPECT_THROW(Image8::make(4, -1, 3), engine::Error);
}

TEST(CaptureImage, AlphaIsFoundByNameIncludingLayerPrefixes) {
    EXPECT_EQ(findAlphaChannel(std::vector<std::string>{"Y", "A"}), 1);
    EXPECT_EQ(findAlphaChannel(std::vector<std::string>{"opaque.R", "opaque.A"}), 1);
    EXPECT_EQ(findAlphaChannel(std::vector<std::string>{"R", "G", "B"}), -1);
}

TEST(CaptureImage, PremultiplyAndBackKeepsColourWhereAlphaIsNotZero) {
    Image image = Image::make(2, 1, 4, AlphaMode::Straight);
    image.fill({0.8f, 0.4f, 0.2f, 0.5f});
    image.at(1, 0, 3) = 0.0f;  // alpha 0: premultiplying loses this pixel's colour
    premultiply(image);
    EXPECT_EQ(image.alpha, AlphaMode::Premultiplied);
    EXPECT_FLOAT_EQ(image.at(0, 0, 0), 0.4f);
    EXPECT_EQ(image.at(1, 0, 0), 0.0f);
    unpremultiply(image);
    EXPECT_EQ(image.alpha, AlphaMode::Straight);
    EXPECT_FLOAT_EQ(image.at(0, 0, 0), 0.8f);
    EXPECT_EQ(image.at(1, 0, 0), 0.0f);
}
