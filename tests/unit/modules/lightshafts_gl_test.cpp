// SPDX-License-Identifier: MIT
// modules/lightshafts on the GL backend: the sun-visibility occlusion query and the
// conditional shaft pass (glBeginConditionalRender) skip the pass exactly when the soft
// backend does, and the frames agree with soft's.
#include <gtest/gtest.h>

#include "engine/render/gl/gl_backend.hpp"
#include "engine/render/soft/soft_backend.hpp"
#include "lightshafts/light_shaft_feature.hpp"
#include "shaft_scene.hpp"

namespace {

using namespace engine;
using living::testing::kSunAhead;
using living::testing::ShaftScene;

struct Outcome {
    render::Readback frame;
    bool sunVisible = false;
    bool shaftPassSkipped = false;
};

Outcome run(std::unique_ptr<render::Backend> backend, const std::vector<living::testing::Card>& cards) {
    ShaftScene s(std::move(backend), cards);
    lightshafts::LightShaftFeature f(*s.backend);
    s.backend->takeTimings();
    Outcome o;
    o.frame = s.render(&f, kSunAhead);
    o.sunVisible = f.sunVisible();
    for (const render::PassTiming& t : s.backend->takeTimings())
        if (t.pass == "light shafts") o.shaftPassSkipped = t.skipped;
    return o;
}

float maxDifference(const render::Readback& a, const render::Readback& b) {
    float m = 0.0f;
    for (std::size_t i = 0; i < a.values.size(); ++i) m = std::max(m, std::abs(a.values[i] - b.values[i]));
    return m;
}

TEST(LightShaftsGl, FullyOccludedSunSkipsThePassAsOnSoft) {
    for (const auto& cards : {living::testing::canopyOverTheSun(), living::testing::canopyWithAGap()}) {
        const Outcome soft = run(render::soft::createSoftBackend({1, 64, false}), cards);
        const Outcome gl = run(render::gl::createGlBackend(), cards);
        EXPECT_EQ(gl.sunVisible, soft.sunVisible);
        EXPECT_EQ(gl.shaftPassSkipped, soft.shaftPassSkipped);
        EXPECT_EQ(gl.shaftPassSkipped, !gl.sunVisible);
        // RGBA8 target: 2 codes, as the other soft-vs-GL living-scene checks (README).
        EXPECT_LE(maxDifference(gl.frame, soft.frame), 2.0f / 255.0f + 1e-6f);
    }
    EXPECT_TRUE(run(render::gl::createGlBackend(), living::testing::canopyOverTheSun()).shaftPassSkipped);
    EXPECT_FALSE(run(render::gl::createGlBackend(), living::testing::canopyWithAGap()).shaftPassSkipped);
}

}  // namespace
