// SPDX-License-Identifier: MIT
// SSAM's passes on Vulkan against the soft backend, one EXR layer at a time: racer renders the
// technique_ssam golden's frame (the pan, frame 2, the paper's knobs, the living scene off) on
// both backends with --capture-layers, Vulkan under the validation layer (SSAM_VK_VALIDATION=1:
// any message fails the run), and every layer of the soft EXR (opaque, depth, the masks, the
// foliage colour and depth, the result) is compared with the same layer of the Vulkan EXR.
//
// Tolerance per layer: the GL goldens' (tests/README.md): at most 0.05 % of the pixels may
// differ by more than 0.1 in a channel. lavapipe is llvmpipe's rasterizer, so the same few
// foliage-edge pixels flip between leaf and background (sample positions, edge ties and blend
// rounding are the implementation's in Vulkan as in GL). Each layer's measured figures are
// printed, so a layer that drifts shows which pass it is.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "engine/capture/exr_layers.hpp"

namespace {

namespace fs = std::filesystem;
namespace cap = engine::capture;

constexpr float kFail = 0.1f;          // per channel, as Racer.GoldenGl / GoldenVk
constexpr double kFailPercent = 0.05;  // of the pixels, as Racer.GoldenGl / GoldenVk

// racer's layers of one backend: <dir>/<backend>.exr beside <backend>.png.
fs::path renderLayers(const std::string& backend, const fs::path& dir) {
    const fs::path png = dir / (backend + ".png");
    const std::string command = std::string("DISPLAY= SSAM_VK_VALIDATION=1 '") + SSAM_RACER + "' --backend " + backend +
                                " --headless --size 320x180 --ssam-preset paper --no-wind --no-water --no-grass"
                                " --no-particles --no-lightshafts --technique ssam --camera pan --frames 2"
                                " --capture '" +
                                png.string() + "' --capture-layers > '" + (dir / (backend + ".log")).string() +
                                "' 2>&1";
    const int rc = std::system(command.c_str());
    EXPECT_EQ(rc, 0) << command << " (log: " << (dir / (backend + ".log")).string() << ")";
    return fs::path(png).replace_extension(".exr");
}

TEST(VkLayers, EverySsamLayerMatchesTheSoftBackend) {
    const fs::path dir = fs::path(SSAM_BINARY_DIR) / "out" / "vk_layers";
    fs::create_directories(dir);
    const fs::path soft = renderLayers("soft", dir), vk = renderLayers("vk", dir);
    ASSERT_TRUE(fs::exists(soft) && fs::exists(vk));
    const std::vector<std::string> layers = cap::listExrLayers(soft);
    EXPECT_EQ(cap::listExrLayers(vk), layers);
    EXPECT_GE(layers.size(), 7u) << "opaque, depth, mask_max, mask_add, foliage, foliage_depth, result";
    for (const std::string& name : layers) {
        const cap::Image s = cap::readExrLayer(soft, name), v = cap::readExrLayer(vk, name);
        ASSERT_EQ(s.width, v.width) << name;
        ASSERT_EQ(s.height, v.height) << name;
        ASSERT_EQ(s.channelNames, v.channelNames) << name;
        std::size_t over = 0, differ = 0;
        float worst = 0.0f;
        for (std::size_t p = 0; p < s.pixelCount(); ++p) {
            float d = 0.0f;
            for (int c = 0; c < s.channels; ++c)
                d = std::max(d, std::fabs(s.pixels[p * std::size_t(s.channels) + std::size_t(c)] -
                                          v.pixels[p * std::size_t(s.channels) + std::size_t(c)]));
            worst = std::max(worst, d);
            over += d > kFail;
            differ += d > 0.0f;
        }
        const double percent = 100.0 * double(over) / double(s.pixelCount());
        std::printf("layer %-14s %zu of %zu pixels differ, %zu over %.2f (%.4f %%), worst %.6f\n", name.c_str(), differ,
                    s.pixelCount(), over, double(kFail), percent, double(worst));
        EXPECT_LE(percent, kFailPercent) << "layer " << name << ": " << over << " pixels over " << kFail;
    }
}

}  // namespace
