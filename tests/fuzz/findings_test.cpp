// SPDX-License-Identifier: MIT
// The fixes for what fuzzing found (tests/fuzz), checked directly. The seed-corpus replays
// catch escaping exceptions, broken contracts, crashes and hangs, but a read past a buffer
// that does not crash shows only under a sanitizer, and a silently wrong value only to a
// test that knows the right one.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

#include "engine/assets/gltf.hpp"
#include "engine/assets/image.hpp"
#include "engine/capture/exr_layers.hpp"
#include "engine/capture/image_read.hpp"
#include "engine/capture/jpeg_metadata.hpp"
#include "expect_error.hpp"

namespace {

using engine::capture::withoutJpegMetadata;

std::filesystem::path seed(const std::string& target, const std::string& name) {
    return std::filesystem::path(SSAM_SOURCE_DIR) / "tests" / "fuzz" / "corpus" / target / name;
}

std::vector<std::uint8_t> readBytes(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The byte positions where two buffers of one size differ.
std::vector<std::size_t> differences(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b) {
    std::vector<std::size_t> at;
    for (std::size_t i = 0; i < a.size() && i < b.size(); ++i)
        if (a[i] != b[i]) at.push_back(i);
    return at;
}

// OpenImageIO 2.4 read the IPTC block of this file's APP13 segment for the length the block
// claims (125 bytes), past the end of the 91-byte segment (ASan: heap-buffer-overflow in
// decode_iptc_iim). The segment sits at byte 0x7E, after bytes libjpeg skips as garbage.
TEST(FuzzFindings, JpegIptcSegmentIsHiddenFromOpenImageIO) {
    const auto original = readBytes(seed("image_decode", "regress_jpeg_iptc_size_past_segment.jpg"));
    ASSERT_GT(original.size(), 0x80u);
    ASSERT_EQ(original[0x7E], 0xFF);
    ASSERT_EQ(original[0x7F], 0xED);  // APP13
    const auto cleaned = withoutJpegMetadata(original);
    ASSERT_EQ(cleaned.size(), original.size());
    const auto changed = differences(original, cleaned);
    EXPECT_THAT(changed, ::testing::Contains(0x7Fu));
    for (std::size_t at : changed) {  // only marker bytes, each APP1, APP2 or APP13 turned APP15
        EXPECT_EQ(original[at - 1], 0xFF) << "byte " << at;
        EXPECT_THAT(original[at], ::testing::AnyOf(0xE1, 0xE2, 0xED)) << "byte " << at;
        EXPECT_EQ(cleaned[at], 0xEF) << "byte " << at;  // skipped by libjpeg, never parsed by OpenImageIO
    }
}

// The walk is libjpeg's: fill bytes, garbage before a marker and FF 00 are stepped over, the
// metadata segments OpenImageIO keeps (APP1, APP2, APP13) are renamed, nothing after the
// first scan is touched.
TEST(FuzzFindings, JpegMetadataWalkFollowsLibjpeg) {
    const std::vector<std::uint8_t> jpeg = {
        0xFF, 0xD8,                                      // SOI
        0xFF, 0xE0, 0x00, 0x04, 0xAA, 0xBB,              // APP0 (kept)
        0xFF, 0xE1, 0x00, 0x02,                          // APP1, empty
        0x12, 0x34, 0xFF, 0x00,                          // garbage and FF 00 before the next marker
        0xFF, 0xFF, 0xED, 0x00, 0x03, 0xFF,              // fill byte, APP13 holding an FF
        0xFF, 0xE2, 0x00, 0x02,                          // APP2
        0xFF, 0xEE, 0x00, 0x02,                          // APP14 (kept)
        0xFF, 0xDA, 0x00, 0x02, 0xFF, 0xE1, 0xFF, 0xD9,  // SOS, then scan data that looks like APP1
    };
    const auto cleaned = withoutJpegMetadata(jpeg);
    EXPECT_THAT(differences(jpeg, cleaned), ::testing::ElementsAre(9u, 18u, 23u));
    EXPECT_EQ(cleaned[9], 0xEF);
    EXPECT_EQ(cleaned[18], 0xEF);
    EXPECT_EQ(cleaned[23], 0xEF);
    const std::vector<std::uint8_t> png = {0x89, 'P', 'N', 'G', 0xFF, 0xE1};
    EXPECT_EQ(withoutJpegMetadata(png), png);
}

// Hiding the metadata changes no pixel: decodeImage matches OpenImageIO on the untouched file
// (a JPEG written by oiiotool, with Exif and IPTC segments).
TEST(FuzzFindings, JpegPixelsAreUnchanged) {
    const std::filesystem::path file = seed("image_decode", "jpeg_rgb.jpg");
    const auto bytes = readBytes(file);
    ASSERT_NE(withoutJpegMetadata(bytes), bytes) << "the seed should carry metadata segments";
    auto input = OIIO::ImageInput::open(file.string());
    ASSERT_TRUE(input);
    const OIIO::ImageSpec spec = input->spec();
    ASSERT_EQ(spec.nchannels, 3);
    std::vector<std::uint8_t> expected(static_cast<std::size_t>(spec.width * spec.height * 3));
    ASSERT_TRUE(input->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, expected.data()));

    const engine::assets::RgbaImage decoded = engine::assets::decodeImage(bytes, "jpeg_rgb.jpg");
    ASSERT_EQ(decoded.width, spec.width);
    ASSERT_EQ(decoded.height, spec.height);
    for (std::size_t t = 0; t < decoded.pixelCount(); ++t)
        for (std::size_t c = 0; c < 3; ++c) ASSERT_EQ(decoded.pixels[t * 4 + c], expected[t * 3 + c]) << "texel " << t;
}

// Finite numbers whose products are not: refused, naming the node or the attribute.
TEST(FuzzFindings, OverflowingProductsAreRefused) {
    ssam::testing::expectError([] { engine::assets::loadGltf(seed("gltf_glb", "world_transform_overflow.glb")); },
                               "nodes[1]: the world transform (the parents' transforms times this node's) "
                               "overflows the float range");
    ssam::testing::expectError([] { engine::assets::loadGltf(seed("gltf_glb", "world_bounds_overflow.glb")); },
                               "nodes[1].mesh: the mesh's bounds in world space overflow the float range");
    ssam::testing::expectError(
        [] { engine::assets::loadGltf(seed("gltf_text", "texture_transform_overflow.gltf")); },
        "meshes[0].primitives[0].attributes.TEXCOORD_0: element 1: KHR_texture_transform of material 0 takes the UV "
        "out of the float range");
}

// A quaternion with components near FLT_MAX ([3e38, 0, 0, 3e38]: 90 degrees about +X) had a
// float length of infinity and became the identity rotation without a word.
TEST(FuzzFindings, HugeQuaternionStillRotates) {
    const engine::assets::LoadedModel model = engine::assets::loadGltf(seed("gltf_text", "quaternion_huge.gltf"));
    ASSERT_GE(model.nodes.size(), 2u);
    const glm::mat4& local = model.nodes[1].local;  // rotation, then scale 2
    EXPECT_NEAR(local[1].y, 0.0f, 1e-5f);           // +Y turns to +Z
    EXPECT_NEAR(local[1].z, 2.0f, 1e-5f);
    EXPECT_NEAR(local[2].y, -2.0f, 1e-5f);  // +Z turns to -Y
    EXPECT_NEAR(local[0].x, 2.0f, 1e-5f);
}

// A 364-byte EXR whose header declares a 1.75 GiB attribute of an unknown type: OpenEXR 3.1
// allocated it before finding the file too short (seconds under ASan: a fuzzing "timeout"; an
// int32 size allows 2 GiB). Refused from the header walk, before OpenEXR sees the file, by
// every reader, the type's control byte spelled out.
TEST(FuzzFindings, ExrAttributeLargerThanTheFileIsRefused) {
    const std::filesystem::path file = seed("capture_image", "regress_exr_attribute_size_past_end.exr");
    const std::string expected = "image '" + file.string() +
                                 "': corrupt EXR: header attribute 'compresslineOrder' of type '\\x01' declares "
                                 "1879048192 bytes, the file has 239 left";
    ssam::testing::expectError([&] { engine::capture::readImage(file); }, expected);
    ssam::testing::expectError([&] { engine::capture::readImage8(file); }, expected);
    ssam::testing::expectError([&] { engine::capture::listExrLayers(file); }, expected);
}

// The walk goes through every part's header of a multi-part file, and accepts the seeds.
TEST(FuzzFindings, ExrHeaderWalkReadsEveryPart) {
    std::vector<std::uint8_t> exr = {0x76, 0x2F, 0x31, 0x01, 0x02, 0x10, 0x00, 0x00};  // version 2, multi-part
    const auto attribute = [&](const std::string& name, const std::string& type, std::uint32_t size) {
        exr.insert(exr.end(), name.begin(), name.end());
        exr.push_back(0);
        exr.insert(exr.end(), type.begin(), type.end());
        exr.push_back(0);
        for (int b = 0; b < 4; ++b) exr.push_back(static_cast<std::uint8_t>(size >> (8 * b)));
    };
    attribute("name", "string", 1);
    exr.push_back('a');
    exr.push_back(0);  // end of the first part's header
    attribute("second", "int", 0x7FFFFFFF);
    exr.insert(exr.end(), 16, 0);
    const std::filesystem::path file = std::filesystem::temp_directory_path() / "ssam_findings_multipart.exr";
    {
        std::ofstream out(file, std::ios::binary);
        out.write(reinterpret_cast<const char*>(exr.data()), static_cast<std::streamsize>(exr.size()));
    }
    ssam::testing::expectError([&] { engine::capture::readImage(file); },
                               "corrupt EXR: header attribute 'second' of type 'int' declares 2147483647 bytes, the "
                               "file has 16 left");
    std::filesystem::remove(file);
    for (const char* name : {"exr_float_nan_rgba.exr", "exr_depth_nan_inf.exr", "exr_rgba_half.exr"})
        EXPECT_NO_THROW(engine::capture::readImage(seed("capture_image", name))) << name;
}

}  // namespace
