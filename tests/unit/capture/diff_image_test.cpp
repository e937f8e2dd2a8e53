// SPDX-License-Identifier: MIT
#include <gtest/gtest.h>

#include "engine/capture/diff_image.hpp"
#include "engine/capture/image_read.hpp"
#include "engine/core/error.hpp"
#include "temp_dir.hpp"

using namespace engine::capture;

TEST(CaptureDiffImage, IsTheScaledAbsoluteDifference) {
    Image a = Image::make(2, 1, 3);
    Image b = Image::make(2, 1, 3);
    a.fill({0.5f, 0.25f, 0.0f});
    b.fill({0.25f, 0.5f, 0.0f});
    const Image diff = absoluteDifference(a, b, 2.0f);
    EXPECT_EQ(diff.pixels, (std::vector<float>{0.5f, 0.5f, 0.0f, 0.5f, 0.5f, 0.0f}));
    EXPECT_THROW(absoluteDifference(a, Image::make(1, 1, 3)), engine::Error);
}

TEST(CaptureDiffImage, IsWrittenAsPngWithoutTheSrgbCurveAndAsExr) {
    ssam::testing::TempDir dir;
    Image a = Image::make(3, 2, 3);
    Image b = a;
    b.at(1, 1, 0) = 1.0f / 255.0f;
    b.at(2, 0, 2) = 0.25f;
    writeDiffImage(dir / "diff.png", a, b, 4.0f);
    ASSERT_TRUE(std::filesystem::exists(dir / "diff.png"));
    const Image8 codes = readImage8(dir / "diff.png");
    EXPECT_EQ(codes.at(1, 1, 0), 4);    // (1/255) * 4, stored linearly
    EXPECT_EQ(codes.at(2, 0, 2), 255);  // 0.25 * 4 = 1
    EXPECT_EQ(codes.at(0, 0, 0), 0);

    writeDiffImage(dir / "diff.exr", a, b, 1.0f);
    const Image exr = readImage(dir / "diff.exr");
    EXPECT_EQ(exr.at(2, 0, 2), 0.25f);
    EXPECT_THROW(writeDiffImage(dir / "diff.bmpx", a, b), engine::Error);
}
