// SPDX-License-Identifier: MIT
#include <gtest/gtest.h>

#include "engine/capture/exr_layers.hpp"
#include "engine/capture/image_read.hpp"
#include "engine/core/error.hpp"
#include "temp_dir.hpp"

using namespace engine::capture;

namespace {
// Distinct, non-representable-in-half values so a mixed-up channel or a lost float is caught.
Image patterned(std::vector<std::string> names, float seed) {
    Image image = Image::make(5, 3, std::move(names));
    for (std::size_t i = 0; i < image.pixels.size(); ++i)
        image.pixels[i] = seed + 0.001f * static_cast<float>(i) + 1e-7f;
    return image;
}
}  // namespace

TEST(CaptureExrLayers, WritesNamedLayersAndReadsEachBack) {
    ssam::testing::TempDir dir;
    const Image opaque = patterned({"R", "G", "B", "A"}, 0.1f);
    const Image mask = patterned({"Y"}, 0.2f);
    const Image foliage = patterned({"R", "G", "B", "A"}, 0.3f);
    const Image depth = patterned({"Z"}, 10.0f);
    const Image result = patterned({"R", "G", "B", "A"}, 0.5f);
    const auto path = dir / "layers.exr";
    writeExrLayers(path,
                   {{"opaque", opaque}, {"mask", mask}, {"foliage", foliage}, {"depth", depth}, {"result", result}});

    const auto layers = listExrLayers(path);
    for (const char* name : {"opaque", "mask", "foliage", "depth", "result"})
        EXPECT_NE(std::find(layers.begin(), layers.end(), name), layers.end()) << name;
    EXPECT_EQ(layers.size(), 5u);

    for (const auto& [name, written] : std::vector<std::pair<std::string, const Image*>>{
             {"opaque", &opaque}, {"mask", &mask}, {"foliage", &foliage}, {"depth", &depth}, {"result", &result}}) {
        const Image read = readExrLayer(path, name);
        EXPECT_EQ(read.channelNames, written->channelNames) << name;
        EXPECT_EQ(read.alpha, AlphaMode::Premultiplied);
        EXPECT_EQ(read.pixels, written->pixels) << name;  // float layers are exact
    }

    // Whole-file view: channels carry the layer prefix.
    const Image all = readImage(path);
    EXPECT_EQ(all.channels, 4 + 1 + 4 + 1 + 4);
    EXPECT_GE(all.channelIndex("depth.Z"), 0);
    EXPECT_GE(all.channelIndex("opaque.A"), 0);
}

TEST(CaptureExrLayers, HalfLayersAreRoundedAndFloatLayersExact) {
    ssam::testing::TempDir dir;
    const Image colour = patterned({"R", "G", "B"}, 0.3f);
    const Image depth = patterned({"Z"}, 1000.0f);
    const auto path = dir / "mixed.exr";
    writeExrLayers(path, {{"colour", colour, ExrPixelType::Half}, {"depth", depth, ExrPixelType::Float}});
    const Image colourBack = readExrLayer(path, "colour");
    for (std::size_t i = 0; i < colour.pixels.size(); ++i) EXPECT_NEAR(colourBack.pixels[i], colour.pixels[i], 1e-3f);
    EXPECT_EQ(readExrLayer(path, "depth").pixels, depth.pixels);
}

TEST(CaptureExrLayers, StraightLayersArePremultipliedOnWrite) {
    ssam::testing::TempDir dir;
    Image straight = Image::make(1, 1, 4, AlphaMode::Straight);
    straight.fill({0.5f, 1.0f, 0.25f, 0.5f});
    writeExrLayers(dir / "straight.exr", {{"foliage", straight}});
    const Image back = readExrLayer(dir / "straight.exr", "foliage");
    EXPECT_EQ(back.pixels, (std::vector<float>{0.25f, 0.5f, 0.125f, 0.5f}));
}

TEST(CaptureExrLayers, MissingLayerNamesTheFileAndTheLayersItHas) {
    ssam::testing::TempDir dir;
    const auto path = dir / "one.exr";
    writeExrLayers(path, {{"opaque", patterned({"R", "G", "B", "A"}, 0.0f)}});
    try {
        readExrLayer(path, "mask");
        FAIL() << "expected engine::Error";
    } catch (const engine::Error& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find(path.string()), std::string::npos) << what;
        EXPECT_NE(what.find("'mask'"), std::string::npos) << what;
        EXPECT_NE(what.find("'opaque'"), std::string::npos) << what;
    }
}

TEST(CaptureExrLayers, InconsistentLayersAreRefused) {
    ssam::testing::TempDir dir;
    const Image small = Image::make(2, 2, 1);
    const Image large = Image::make(3, 2, 1);
    EXPECT_THROW(writeExrLayers(dir / "sizes.exr", {{"a", small}, {"b", large}}), engine::Error);
    EXPECT_THROW(writeExrLayers(dir / "twice.exr", {{"a", small}, {"a", small}}), engine::Error);
    EXPECT_THROW(writeExrLayers(dir / "unnamed.exr", {{"", small}, {"b", small}}), engine::Error);
    EXPECT_THROW(writeExrLayers(dir / "none.exr", {}), engine::Error);
}
