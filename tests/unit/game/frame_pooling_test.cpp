// SPDX-License-Identifier: MIT
// The racing frame as racer builds it (frame graph, every living-scene module on) creates no
// texture or buffer once it runs steadily: per-frame instance buffers and the graph's
// transient targets come from pools (engine/render frame_buffer_pool.hpp,
// transient_texture_pool.hpp). Counted through a backend decorator; the GL case is
// frame_pooling_gl_test.cpp (label gl).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

#include "engine/render/forwarding_backend.hpp"
#include "engine/scene/components.hpp"

#include "engine/render/soft/soft_backend.hpp"
#include "racing_frame.hpp"

namespace {

using namespace racer;
using racer::testing::RacingFrame;

TEST(FramePooling, SteadyRacingFramesCreateNothingOnSoft) {
    auto soft = engine::render::soft::createSoftBackend({2, 64, false});
    racer::testing::expectNoCreationsInSteadyState(*soft);
}

// With levels of detail (racer's default): while the car drives off the plants change level and
// the wind hands deformed copies back and forth; once steady, nothing is created.
TEST(FramePooling, SteadyRacingFramesWithLevelsOfDetailCreateNothingOnSoft) {
    auto soft = engine::render::soft::createSoftBackend({2, 64, false});
    racer::testing::expectNoCreationsInSteadyState(*soft, /*levelsOfDetail=*/true);
}

// A steady frame in which plants crossfade between levels (both drawn, their weights in the
// instance tint) creates nothing either: the two levels' instances share the pooled buffers.
TEST(FramePooling, SteadyFramesWithCrossfadingPlantsCreateNothingOnSoft) {
    auto soft = engine::render::soft::createSoftBackend({2, 64, false});
    ssam::testing::FailingBackend backend(*soft);
    RacingFrame frame(backend, /*levelsOfDetail=*/true);
    frame.run(0, 30);
    frame.run(30, 1, CameraMode::Chase, /*paused=*/true);  // the steady frame's levels
    int crossfading = 0;
    frame.scene.registry().view<const engine::scene::LevelsOfDetail>().each(
        [&](engine::ecs::Entity, const engine::scene::LevelsOfDetail& lod) { crossfading += lod.blend.crossfading(); });
    ASSERT_GT(crossfading, 0) << "no plant inside a crossfade band: the case is not exercised";
    const int createsBefore = backend.creates;
    frame.run(30, 20, CameraMode::Chase, /*paused=*/true);
    EXPECT_EQ(backend.creates - createsBefore, 0) << "textures or buffers created in 20 steady crossfading frames";
}

// The wind's motion copies (of every bent plant part, in buffers of their own) are made only
// while the frame's technique reads motion vectors (FrameRenderer::needsMotionVectors ->
// scene::SimulationFrame::motionVectors): none under SSAM, some once hashed+taa runs; and
// hashed+taa's steady frames, motion copies and all, create nothing.
int motionCopiesDrawn(RacingFrame& frame) {
    int copies = 0;
    frame.scene.registry().view<const engine::scene::VertexOverride>().each(
        [&](engine::ecs::Entity, const engine::scene::VertexOverride& o) {
            for (engine::render::BufferHandle b : o.motionBuffers) copies += bool(b);
        });
    return copies;
}

TEST(FramePooling, MotionCopiesOnlyForATechniqueThatReadsThemAndSteadyFramesCreateNothing) {
    auto soft = engine::render::soft::createSoftBackend({2, 64, false});
    ssam::testing::FailingBackend backend(*soft);
    RacingFrame frame(backend);
    ASSERT_FALSE(frame.renderer.needsMotionVectors());
    frame.run(0, 10);
    int bent = 0;
    frame.scene.registry().view<const engine::scene::VertexOverride>().each(
        [&](engine::ecs::Entity, const engine::scene::VertexOverride&) { ++bent; });
    ASSERT_GT(bent, 0) << "no plant bent: the case is not exercised";
    EXPECT_EQ(motionCopiesDrawn(frame), 0)
        << "motion copies made for " << transparency::techniqueName(frame.renderer.technique());

    frame.renderer.setTechnique(transparency::TechniqueKind::HashedTaa);
    ASSERT_TRUE(frame.renderer.needsMotionVectors());
    frame.run(10, 20);
    EXPECT_GT(motionCopiesDrawn(frame), 0) << "hashed+taa reads motion vectors, the wind made none";
    // The car moves rigidly (engine/scene rigid_motion.hpp): its opaque batches carry its motion.
    const engine::scene::VertexOverride* car =
        frame.scene.registry().tryGet<engine::scene::VertexOverride>(frame.scene.car());
    ASSERT_NE(car, nullptr) << "the car has no motion copy under hashed+taa";
    EXPECT_TRUE(std::any_of(car->motionBuffers.begin(), car->motionBuffers.end(),
                            [](engine::render::BufferHandle b) { return bool(b); }));
    frame.run(30, 1, CameraMode::Chase, /*paused=*/true);
    const int createsBefore = backend.creates;
    frame.run(30, 20, CameraMode::Chase, /*paused=*/true);
    EXPECT_EQ(backend.creates - createsBefore, 0) << "textures or buffers created in 20 steady hashed+taa frames";
}

// Counts the textures created through it.
class TextureCounter final : public engine::render::ForwardingBackend {
public:
    using ForwardingBackend::ForwardingBackend;
    int textures = 0;
    engine::render::TextureHandle createTexture(const engine::render::TextureDesc& desc,
                                                const engine::render::TextureData* data) override {
        ++textures;
        return inner_.createTexture(desc, data);
    }
};

// The frame graph owns the frame's intermediates: SSAM's mask and foliage, SSAM+'s, WBOIT's
// accumulators and the particle layer are its transients, created by the passes that draw
// them and backed by the renderer's pool. The same steady frame (paused, chase camera, the
// dust in view) built and executed twice: the second creates no texture, and the dumped
// graph lists those transients with the peak the HUD shows.
struct SteadyFrameCase {
    transparency::TechniqueKind technique;
    std::vector<std::string> transients;  // as the dump's label names them
    std::uint64_t peakBytes;              // the technique's transients, alive together until its last pass
};

class SteadyFrame : public ::testing::TestWithParam<SteadyFrameCase> {};

TEST_P(SteadyFrame, CreatesNoTextureTheSecondTime) {
    auto soft = engine::render::soft::createSoftBackend({2, 64, false});
    TextureCounter backend(*soft);
    RacingFrame frame(backend);
    frame.renderer.setTechnique(GetParam().technique);
    frame.run(0, 30);  // the car drives off and raises dust
    frame.run(30, 1, CameraMode::Chase, /*paused=*/true);
    const int before = backend.textures;
    frame.run(30, 1, CameraMode::Chase, /*paused=*/true);  // the same frame again
    EXPECT_EQ(backend.textures - before, 0) << "textures created by the second of two equal frames";

    std::ostringstream dot;
    frame.renderer.dumpGraph(dot);
    for (const std::string& name : GetParam().transients)
        EXPECT_NE(dot.str().find("  " + name + " "), std::string::npos) << name << " is no transient:\n" << dot.str();
    EXPECT_EQ(frame.renderer.peakTransientBytes(), GetParam().peakBytes) << dot.str();
    EXPECT_NE(dot.str().find("peak transient bytes: " + std::to_string(GetParam().peakBytes)), std::string::npos);
}

// Bytes at 96x54 (racing_frame.hpp): RGBA8 and sRGB 4 per pixel, RGBA16F 8, R16F 2; the
// particle layer (RGBA16F, half resolution: 48x27) lives after the technique's, so it is
// never part of the peak here.
constexpr std::uint64_t kPixels = std::uint64_t(racer::testing::kWidth) * racer::testing::kHeight;
INSTANTIATE_TEST_SUITE_P(
    Techniques, SteadyFrame,
    ::testing::Values(SteadyFrameCase{transparency::TechniqueKind::Ssam,
                                      {"rt_mask", "rt_foliage", "particle layer"},
                                      kPixels*(4 + 4)},
                      SteadyFrameCase{transparency::TechniqueKind::SsamPlus,
                                      {"rt_mask_max", "rt_mask_add", "rt_foliage", "rt_front_layers", "particle layer"},
                                      kPixels*(2 + 2 + 4 + 8)},
                      SteadyFrameCase{transparency::TechniqueKind::Wboit,
                                      {"rt_wboit_accumulation", "rt_wboit_revealage", "particle layer"},
                                      kPixels*(8 + 2)}),
    [](const auto& info) {
        return std::string(transparency::techniqueName(info.param.technique)) == "ssam-plus"
                   ? std::string("ssam_plus")
                   : std::string(transparency::techniqueName(info.param.technique));
    });

// racer --dump-graph: SSAM's passes run in the chase view, and under the sky camera (no
// foliage in view) they are skipped as empty, as is the wheel dust that is out of view.
TEST(FramePooling, TheDumpedGraphMarksSsamEmptyWhenNoFoliageIsInView) {
    auto soft = engine::render::soft::createSoftBackend({2, 64, false});
    RacingFrame frame(*soft);
    frame.run(0, 1);
    std::ostringstream chase;
    frame.renderer.dumpGraph(chase);
    for (const char* pass : {"\"ssam mask\"", "\"ssam colour\"", "\"ssam composite\"", "\"grass", "\"present\""})
        EXPECT_NE(chase.str().find(pass), std::string::npos) << pass << "\n" << chase.str();
    EXPECT_EQ(chase.str().find("ssam mask\\n(empty)"), std::string::npos) << chase.str();

    frame.run(1, 1, CameraMode::Sky);
    std::ostringstream sky;
    frame.renderer.dumpGraph(sky);
    EXPECT_NE(sky.str().find("ssam mask\\n(empty)"), std::string::npos) << sky.str();
    EXPECT_NE(sky.str().find("ssam composite\\n(empty)"), std::string::npos) << sky.str();
}

}  // namespace
