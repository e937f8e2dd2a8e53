// SPDX-License-Identifier: MIT
// The paper's Figures 3.4-3.10 as one multi-layer EXR: every intermediate of an SSAM frame
// captured from the targets and read back from the file.
#include <gtest/gtest.h>

#include <filesystem>

#include "engine/capture/exr_layers.hpp"
#include "engine/capture/target_capture.hpp"
#include "engine/render/frame_targets.hpp"
#include "engine/render/soft/soft_backend.hpp"
#include "quad_scene.hpp"
#include "run_graph.hpp"
#include "ssam/frame_graph_passes.hpp"
#include "ssam/ssam.hpp"

namespace {

using namespace engine::render;
namespace capture = engine::capture;

TEST(SsamCapture, EveryIntermediateIsALayerOfOneExr) {
    auto backend = soft::createSoftBackend({});
    engine::render::FrameTargets opaque(*backend, {16, 16, 1, Format::RGBA8_SRGB, CompareFunc::Less});
    backend->beginPass(opaque.passDesc({0.2f, 0.4f, 0.6f, 1.0f}));
    backend->endPass();
    ssam::testing::QuadBatches quads(*backend, {{-1.0f, -1.0f, 0.25f, 1.0f, 0.3f, {1.0f, 0.0f, 0.0f, 0.4f}},
                                                {-0.25f, -1.0f, 1.0f, 1.0f, 0.6f, {0.0f, 1.0f, 0.0f, 0.2f}}});
    const DirectionalLight unlit{{0, 0, 1}, glm::vec3(0.0f), glm::vec3(1.0f)};
    ssam::ScreenSpaceAlphaMask ssam(*backend, [] {
        ssam::Settings c;
        c.maskPrecision = ssam::MaskPrecision::Rgba16f;
        return c;
    }());

    std::vector<capture::CapturedLayer> layers;
    layers.push_back(capture::captureTarget(*backend, opaque.color(), "opaque"));
    layers.push_back(capture::captureTarget(*backend, opaque.depth(), "depth"));
    // SSAM's passes as the racer runs them; its intermediates are captured before the graph releases them.
    test_support::OneFrameGraph frame(*backend);
    const ssam::FoliageView view{glm::mat4(1.0f), unlit, quads.batches};
    const ssam::SsamPasses passes =
        ssam::addSsamPasses(frame.graph(), ssam, view, frame.import(opaque.color(), opaque.depth()));
    capture::CapturedLayer mask, foliage;
    frame.use({passes.mask, passes.foliage}, [&](const std::vector<TextureHandle>& t) {
        mask = capture::captureTarget(*backend, t[0], "mask");
        foliage = capture::captureTarget(*backend, t[1], "foliage");
    });
    frame.run(passes.frame);
    capture::CapturedLayer maskMax{"mask_max", capture::Image::make(16, 16, std::vector<std::string>{"Y"})};
    capture::CapturedLayer maskAdd{"mask_add", capture::Image::make(16, 16, std::vector<std::string>{"Y"})};
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x) {
            maskMax.image.at(x, y, 0) = mask.image.at(x, y, 0);
            maskAdd.image.at(x, y, 0) = mask.image.at(x, y, 3);
        }
    layers.push_back(std::move(maskMax));
    layers.push_back(std::move(maskAdd));
    layers.push_back(std::move(foliage));
    layers.push_back(capture::captureTarget(*backend, opaque.depth(), "foliage_depth"));
    layers.push_back(capture::captureTarget(*backend, opaque.color(), "result"));

    const auto path = std::filesystem::temp_directory_path() / "ssam_capture_layers_test.exr";
    capture::writeLayersExr(path, layers);
    const auto names = capture::listExrLayers(path);
    for (const char* expected : {"opaque", "depth", "mask_max", "mask_add", "foliage", "foliage_depth", "result"})
        EXPECT_NE(std::find(names.begin(), names.end(), expected), names.end()) << expected;

    EXPECT_NEAR(capture::readExrLayer(path, "mask_add").at(8, 4, 0), 0.6f, 1e-3f);  // 0.4 + 0.2
    EXPECT_NEAR(capture::readExrLayer(path, "mask_max").at(8, 4, 0), 0.4f, 1e-3f);
    EXPECT_FLOAT_EQ(capture::readExrLayer(path, "depth").at(8, 4, 0), 1.0f);             // before the colour pass
    EXPECT_NEAR(capture::readExrLayer(path, "foliage_depth").at(8, 4, 0), 0.3f, 1e-6f);  // after it
    const capture::Image result = capture::readExrLayer(path, "result");
    const capture::Image opaqueLayer = capture::readExrLayer(path, "opaque");
    EXPECT_GT(result.at(8, 4, 0), opaqueLayer.at(8, 4, 0));  // red foliage blended in
    std::filesystem::remove(path);
}

}  // namespace
