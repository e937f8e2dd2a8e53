// SPDX-License-Identifier: MIT
// The Vulkan backend's per-pass timings (timestamp queries) are consistent with the wall
// clock around them: each pass's time is >= 0, and the passes of a frame, which run one after
// the other on the one queue, take no longer together than the wall time from before the
// first pass was recorded to after takeTimings returned (it waits for the results). No speed
// is asserted, only consistency. Under validation: any message fails the test.
#include <chrono>
#include <vector>

#include <gtest/gtest.h>

#include <glm/glm.hpp>

#include "draws.hpp"
#include "engine/render/standard_programs.hpp"
#include "engine/render/vertex.hpp"
#include "vk_validation.hpp"

namespace {

using namespace engine::render;
using Clock = std::chrono::steady_clock;
using ssam::testing::meshDraw;
using ssam::testing::validatedVulkanBackend;

struct Scene {
    TextureHandle target;
    BufferHandle vertices;
    PipelineHandle pipeline;
};

// A 256x256 target and a triangle covering most of it, blended so every draw shades.
Scene makeScene(Backend& gfx) {
    std::vector<Vertex> v(3);
    v[0].position = {-1.0f, -1.0f, 0.5f};
    v[1].position = {3.0f, -1.0f, 0.5f};
    v[2].position = {-1.0f, 3.0f, 0.5f};
    for (Vertex& x : v) x.color = {0.2f, 0.4f, 0.6f, 0.5f};
    Scene s;
    s.target = gfx.createTexture(renderTargetDesc("timed target", 256, 256, Format::RGBA16F));
    s.vertices = gfx.createBuffer({"timed triangle", BufferKind::Vertex, v.size() * sizeof(Vertex)},
                                  std::as_bytes(std::span<const Vertex>(v)));
    PipelineDesc pd;
    pd.name = "timed flat";
    pd.program = ProgramKind::Flat;
    pd.blend[0] = BlendState::alphaOver();
    s.pipeline = gfx.createPipeline(pd);
    return s;
}

void timedPass(Backend& gfx, const Scene& s, const std::string& name, int draws) {
    PassDesc pass;
    pass.name = name;
    pass.color[0] = {s.target, LoadOp::Load, glm::vec4(0.0f)};
    gfx.beginPass(pass);
    for (int i = 0; i < draws; ++i)
        gfx.draw(meshDraw(s.pipeline, FlatParams{glm::mat4(1.0f), glm::vec4(1.0f)}, s.vertices, 3));
    gfx.endPass();
}

double millisecondsSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

void expectConsistent(const std::vector<PassTiming>& timings, const std::vector<std::string>& names, double wallMs) {
    ASSERT_EQ(timings.size(), names.size());
    double sum = 0.0;
    for (std::size_t i = 0; i < timings.size(); ++i) {
        EXPECT_EQ(timings[i].pass, names[i]);
        EXPECT_FALSE(timings[i].skipped) << names[i];
        EXPECT_GE(timings[i].milliseconds, 0.0) << names[i];
        sum += timings[i].milliseconds;
    }
    EXPECT_GT(sum, 0.0) << "no pass took any time";
    EXPECT_LE(sum, wallMs) << "the passes' times add up to more than the wall time around them";
}

TEST(VkTimings, PassTimesFitInTheWallTimeAroundTheFrame) {
    auto gfx = validatedVulkanBackend();
    const Scene s = makeScene(*gfx);
    for (int frame = 0; frame < 4; ++frame) {
        SCOPED_TRACE("frame " + std::to_string(frame));
        const Clock::time_point start = Clock::now();
        timedPass(*gfx, s, "a", 40);
        timedPass(*gfx, s, "b", 5);
        timedPass(*gfx, s, "c", 40);
        gfx->endFrame();
        const std::vector<PassTiming> timings = gfx->takeTimings();
        expectConsistent(timings, {"a", "b", "c"}, millisecondsSince(start));
    }
}

// Frames submitted to different frame slots and read together: each pass's own stamps.
TEST(VkTimings, TimingsOfSeveralFramesReadTogetherStayConsistent) {
    auto gfx = validatedVulkanBackend();
    const Scene s = makeScene(*gfx);
    gfx->takeTimings();
    const Clock::time_point start = Clock::now();
    std::vector<std::string> names;
    for (int frame = 0; frame < 3; ++frame) {
        for (int pass = 0; pass < 3; ++pass) {
            names.push_back("f" + std::to_string(frame) + "p" + std::to_string(pass));
            timedPass(*gfx, s, names.back(), 10 + 10 * pass);
        }
        gfx->endFrame();
    }
    const std::vector<PassTiming> timings = gfx->takeTimings();
    expectConsistent(timings, names, millisecondsSince(start));
}

}  // namespace
