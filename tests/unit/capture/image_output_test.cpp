// SPDX-License-Identifier: MIT
// Image outputs: a tool checks the name has a writer before any work
// (requireImageExtension), and every image is written whole or not at all -- through a
// temporary file renamed into place, so neither a partial image nor a temporary is left.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "engine/capture/exr_layers.hpp"
#include "engine/capture/image_write.hpp"
#include "engine/core/error.hpp"
#include "expect_error.hpp"
#include "temp_dir.hpp"

using namespace engine::capture;
namespace fs = std::filesystem;

namespace {

std::vector<std::string> entries(const fs::path& dir) {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(dir)) names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

Image grey() {
    Image image = Image::make(4, 4, 3, AlphaMode::Straight);
    std::fill(image.pixels.begin(), image.pixels.end(), 0.5f);
    return image;
}

TEST(ImageOutput, ExtensionMustHaveAWriter) {
    requireImageExtension("out/frame.png");
    requireImageExtension("out/FRAME.EXR");
    requireImageExtension("frame.png", {".png"});
    ssam::testing::expectError([] { requireImageExtension("frame.txt"); },
                               "image 'frame.txt': the name must end in .png or .exr, not '.txt'");
    ssam::testing::expectError([] { requireImageExtension("frame"); }, "and it has no extension");
    ssam::testing::expectError([] { requireImageExtension("frame.exr", {".png"}); }, "must end in .png, not '.exr'");
}

TEST(ImageOutput, WritesLeaveOnlyTheirTargets) {
    ssam::testing::TempDir dir("ssam_unit_capture");
    const Image image = grey();
    writePng(dir / "a.png", image);
    writeImage(dir / "b.exr", image);
    writeExrLayers(dir / "c.exr", {Layer{"one", image}, Layer{"two", image}});
    EXPECT_EQ(entries(dir.path()), (std::vector<std::string>{"a.png", "b.exr", "c.exr"}));
}

// The target's name is held by a directory: the pixels are written (to the temporary file),
// then the rename fails -- the directory stays and no temporary is left beside it.
TEST(ImageOutput, FailedWriteLeavesNoTemporary) {
    ssam::testing::TempDir dir("ssam_unit_capture");
    fs::create_directories(dir / "frame.png" / "occupied");
    ssam::testing::expectError([&] { writePng(dir / "frame.png", grey()); }, "frame.png");
    EXPECT_EQ(entries(dir.path()), std::vector<std::string>{"frame.png"});
    EXPECT_TRUE(fs::is_directory(dir / "frame.png"));
}

}  // namespace
