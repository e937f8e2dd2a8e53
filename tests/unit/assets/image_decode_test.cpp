// SPDX-License-Identifier: MIT
// decodeImage: PNG bytes in memory -> RGBA8 with straight alpha; grey and RGB files expanded;
// non-images, truncated data and over-cap headers refused with the name in the message.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

#include "assets_test_util.hpp"
#include "engine/assets/image.hpp"

// OpenImageIO 2.4's PNG read callback builds an error string and libpng then longjmps past its
// destructor, leaking a few bytes per truncated PNG (the same known leak unit_capture_read_errors
// suppresses). It is inside the library; tell LeakSanitizer (asan preset) so the truncated
// image test still runs there. Unused in other builds.
extern "C" const char* __lsan_default_suppressions() {
    return "leak:OpenImageIO_v2_4::PNGInput::PngReadCallback\n"
           "leak:OpenImageIO_v2_4::ImageInput::geterror\n";
}
// The leaked blocks are allocated in libstdc++ on the library's behalf, and neither library keeps
// frame pointers: the fast unwinder's stack may stop in libstdc++ before reaching a frame the
// suppressions name (it did at -O1). The slow unwinder reaches them; only this binary pays for it.
extern "C" const char* __asan_default_options() { return "fast_unwind_on_malloc=0"; }

namespace {

using assets_test::errorOf;
using assets_test::fixture;
using engine::assets::decodeImage;
using ::testing::HasSubstr;

std::vector<std::uint8_t> readBytes(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(ImageDecode, PngKeepsStraightAlphaAndStoredCodes) {
    const auto image = decodeImage(readBytes(fixture("leaf4.png")), "leaf4.png");
    ASSERT_EQ(image.width, 4);
    ASSERT_EQ(image.height, 4);
    EXPECT_EQ(image.alpha, engine::render::AlphaMode::Straight);
    EXPECT_TRUE(image.srgb);
    // Corner: alpha 0 but its straight colour survives (premultiplying would zero it).
    const std::uint8_t* corner = image.texel(0, 0);
    EXPECT_EQ(corner[0], 40);
    EXPECT_EQ(corner[1], 140);
    EXPECT_EQ(corner[2], 30);
    EXPECT_EQ(corner[3], 0);
    EXPECT_EQ(image.texel(3, 2)[1], 200);
}

TEST(ImageDecode, RefusesNonImagesAndTruncatedData) {
    const std::vector<std::uint8_t> text = {'h', 'e', 'l', 'l', 'o'};
    EXPECT_EQ(errorOf([&] { decodeImage(text, "x.png"); }),
              "x.png: not a PNG or JPEG image (glTF 2.0 images must be one of these): it starts with the text 'hello'");
    const std::vector<std::uint8_t> gif = {'G', 'I', 'F', '8', '9', 'a', 1, 0, 1, 0};
    EXPECT_EQ(
        errorOf([&] { decodeImage(gif, "z.png"); }),
        "z.png: not a PNG or JPEG image (glTF 2.0 images must be one of these): it starts with the GIF signature");
    EXPECT_EQ(errorOf([&] { decodeImage({}, "y.png"); }), "y.png: empty image data");
    auto png = readBytes(fixture("leaf4.png"));
    ASSERT_GT(png.size(), 30u);
    png.erase(png.end() - 30, png.end());  // cut into the pixel data
    EXPECT_THAT(errorOf([&] { decodeImage(png, "cut.png"); }), HasSubstr("cut.png: "));
}

TEST(ImageDecode, LimitsAreCheckedFromTheHeader) {
    const auto png = readBytes(fixture("leaf4.png"));
    engine::assets::ImageLimits limits;
    limits.maxDimension = 3;
    EXPECT_EQ(errorOf([&] { decodeImage(png, "leaf", limits); }), "leaf: image is 4x4, over the size cap of 3x3");
    limits = {};
    limits.maxDecodedBytes = 32;
    EXPECT_EQ(errorOf([&] { decodeImage(png, "leaf", limits); }),
              "leaf: image is 4x4, 64 bytes decoded, over the cap of 32 bytes");
}

TEST(ImageDecode, GreyAndRgbAreExpandedToOpaqueRgba) {
    const auto grey = decodeImage(readBytes(fixture("grey2x1.png")), "grey");
    ASSERT_EQ(grey.width, 2);
    EXPECT_EQ((std::vector<std::uint8_t>(grey.pixels.begin(), grey.pixels.end())),
              (std::vector<std::uint8_t>{10, 10, 10, 255, 200, 200, 200, 255}));
    const auto rgb = decodeImage(readBytes(fixture("rgb2x1.png")), "rgb");
    EXPECT_EQ((std::vector<std::uint8_t>(rgb.pixels.begin(), rgb.pixels.end())),
              (std::vector<std::uint8_t>{255, 0, 0, 255, 0, 0, 255, 255}));
}

TEST(ImageDecode, MakeRefusesEmptySizes) {
    EXPECT_THAT(errorOf([] { engine::assets::RgbaImage::make(0, 4); }), HasSubstr("not positive"));
    const auto image = engine::assets::RgbaImage::make(3, 2);
    EXPECT_EQ(image.pixels.size(), 24u);
    EXPECT_EQ(image.bytes().size(), 24u);
}

}  // namespace
