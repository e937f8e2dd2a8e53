// SPDX-License-Identifier: MIT
// The default demo shows what SSAM is for: `make demo` without a display runs
// racer --headless --frames 90 --fixed-dt 0.0333333 (chase camera, SSAM, every living-scene
// module). This test runs the same 90 frames the way racer's headless loop does (racer.cpp),
// at 320x180 (the demo's 16:9 at a quarter of its width, so it is quick), and checks, frame by
// frame:
//   - SSAM's mask (the mask_max layer, which racer --capture-layers writes to its EXR) is
//     non-zero on at least kMinFrameCoverage of the pixels, and on kMinMeanCoverage on average
//     over the run: the forest track, not a grass field;
//   - the car is clearly visible: each frame is rendered twice more with the opaque surfaces
//     alone (no foliage, no living scene: no dust, grass, water or light shafts; the
//     simulation steps once per frame, so nothing else changes), with the car and with its
//     model hidden. The car's silhouette is where the opaque pass's depth differs between those
//     two (at least kMinCarPixels: it is in view); on at least kMinCarClear of its pixels the
//     demo's frame may differ from the bare car by at most kVeilCodes (of 255, sRGB) in every
//     channel. Dust or foliage veiling the car, or a camera that loses it, fails here.
// It prints every frame's figures. game/bench/FIGURES.md gives the 1280x720 figures.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include "camera_rig.hpp"
#include "content_dir.hpp"
#include "engine/capture/image_convert.hpp"
#include "engine/capture/readback_image.hpp"
#include "engine/render/soft/soft_backend.hpp"
#include "engine/scene/components.hpp"
#include "engine/scene/draw_lists.hpp"
#include "frame_renderer.hpp"
#include "living_scene.hpp"
#include "racing_scene.hpp"

namespace {

using namespace racer;
namespace capture = engine::capture;

constexpr int kWidth = 320, kHeight = 180;
constexpr int kFrames = 90;
constexpr double kFixedDt = 0.0333333;  // Makefile DEMO_FLAGS
constexpr double kMinMeanCoverage = 0.25;
constexpr double kMinFrameCoverage = 0.10;
constexpr double kMinCarClear = 0.7;
constexpr int kVeilCodes = 24;
constexpr int kMinCarPixels = 400;  // about 1 % of the frame: the car is in view

// The share of pixels where SSAM's MAX mask is above 0 (as `oiiotool --ch mask_max.Y
// --mulc 1e9 --clamp:min=0:max=1 --printstats` measures it from racer's EXR).
double maskCoverage(const FrameRenderer& renderer) {
    for (const capture::CapturedLayer& layer : renderer.layers()) {
        if (layer.name != "mask_max") continue;
        std::size_t covered = 0;
        for (int y = 0; y < layer.image.height; ++y)
            for (int x = 0; x < layer.image.width; ++x) covered += layer.image.at(x, y, 0) > 0.0f;
        return double(covered) / double(layer.image.pixelCount());
    }
    ADD_FAILURE() << "no mask_max layer: is SSAM the technique?";
    return 0.0;
}

const capture::Image& layer(const FrameRenderer& renderer, const char* name) {
    for (const capture::CapturedLayer& l : renderer.layers())
        if (l.name == name) return l.image;
    throw std::runtime_error(std::string("no layer ") + name);
}

capture::Image8 colour(engine::render::Backend& backend, const FrameRenderer& renderer) {
    return capture::encodeSrgbImage(capture::imageFromReadback(backend.readback(renderer.color())));
}

struct CarInSight {
    int pixels = 0;      // the car's silhouette: where the opaque depth changes without it
    double clear = 0.0;  // of those, the share that foliage and dust change by at most kVeilCodes
};

// `depthWith` / `depthWithout`: the opaque depth with and without the car; `demo`: the demo's
// frame; `bare`: the car among the opaque surfaces alone.
CarInSight carInSight(const capture::Image& depthWith, const capture::Image& depthWithout, const capture::Image8& demo,
                      const capture::Image8& bare) {
    CarInSight sight;
    int clear = 0;
    for (int y = 0; y < depthWith.height; ++y)
        for (int x = 0; x < depthWith.width; ++x) {
            if (depthWith.at(x, y, 0) == depthWithout.at(x, y, 0)) continue;
            ++sight.pixels;
            int most = 0;
            for (int c = 0; c < 3; ++c) most = std::max(most, std::abs(int(demo.at(x, y, c)) - int(bare.at(x, y, c))));
            clear += most <= kVeilCodes;
        }
    sight.clear = sight.pixels ? double(clear) / double(sight.pixels) : 0.0;
    return sight;
}

TEST(ForestDemo, SsamMaskCoversTheFrameAndTheCarStaysInSight) {
    auto backend = engine::render::soft::createSoftBackend({2, 64, false});
    RacingScene scene(*backend, SceneOptions{defaultContentDir(), 1});
    RendererOptions options;
    options.width = kWidth;
    options.height = kHeight;
    options.sun = scene.sun();
    options.captureLayers = true;
    FrameRenderer renderer(*backend, scene.library(), options);
    LivingScene living(scene.registry(), scene.library(), LivingSceneOptions{.seed = 1, .track = &scene.track()});
    renderer.setLivingScene(&living);
    ASSERT_EQ(transparency::techniqueName(renderer.technique()), std::string("ssam"));

    engine::ecs::Registry& registry = scene.registry();
    const engine::ecs::Entity car = scene.car();
    const engine::scene::Renderable carModel = registry.get<engine::scene::Renderable>(car);
    const float aspect = float(kWidth) / float(kHeight);

    double coverageSum = 0.0, leastCoverage = 1.0, leastClear = 1.0;
    int leastCoverageFrame = 0, leastClearFrame = 0;
    for (int i = 0; i < kFrames; ++i) {
        const float time = float(i * kFixedDt), dt = float(kFixedDt);
        scene.update(dt);
        const CameraView view = cameraView(CameraMode::Chase, scene, time, aspect, FreeCamera{});
        living.update(time, dt, view);
        renderer.render(engine::scene::extractDrawLists(registry, scene.library(), view.viewProj, view.eye), view);
        const double coverage = maskCoverage(renderer);
        const capture::Image8 demo = colour(*backend, renderer);

        renderer.setLivingScene(nullptr);
        auto opaqueOnly = [&] {
            engine::scene::DrawLists lists =
                engine::scene::extractDrawLists(registry, scene.library(), view.viewProj, view.eye);
            lists.mask.clear();
            lists.blend.clear();
            return lists;
        };
        renderer.render(opaqueOnly(), view);
        const capture::Image depthWith = layer(renderer, "depth");
        const capture::Image8 bare = colour(*backend, renderer);
        registry.remove<engine::scene::Renderable>(car);
        renderer.render(opaqueOnly(), view);
        const CarInSight sight = carInSight(depthWith, layer(renderer, "depth"), demo, bare);
        registry.add<engine::scene::Renderable>(car, carModel);
        renderer.setLivingScene(&living);

        const double clear = sight.pixels >= kMinCarPixels ? sight.clear : 0.0;
        std::printf("frame %2d: mask %5.1f %%, car %4d px, %5.1f %% of them clear\n", i + 1, 100.0 * coverage,
                    sight.pixels, 100.0 * sight.clear);
        coverageSum += coverage;
        if (coverage < leastCoverage) leastCoverage = coverage, leastCoverageFrame = i + 1;
        if (clear < leastClear) leastClear = clear, leastClearFrame = i + 1;
        EXPECT_GE(coverage, kMinFrameCoverage) << "frame " << i + 1 << ": SSAM's mask covers too little";
        EXPECT_GE(clear, kMinCarClear) << "frame " << i + 1 << ": the car is veiled or out of view";
    }
    const double mean = coverageSum / kFrames;
    std::printf("mask coverage: mean %.1f %%, least %.1f %% (frame %d); car clear: least %.1f %% (frame %d)\n",
                100.0 * mean, 100.0 * leastCoverage, leastCoverageFrame, 100.0 * leastClear, leastClearFrame);
    EXPECT_GE(mean, kMinMeanCoverage);
}

}  // namespace
