// SPDX-License-Identifier: MIT
// modules/lightshafts: shafts from the sky the opaque + foliage depth leaves visible;
// foliage over the sun blocks them ([Hathaway 2010] §3.7); off behind the camera; bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "engine/core/error.hpp"
#include "engine/render/soft/soft_backend.hpp"
#include "expect_error.hpp"  // tests/support
#include "lightshafts/light_shaft_feature.hpp"
#include "lightshafts/light_shaft_program.hpp"
#include "shaft_scene.hpp"

namespace {

using namespace engine;
using living::testing::Card;
using living::testing::kSunAhead;
using living::testing::ShaftScene;
constexpr int kW = ShaftScene::kW, kH = ShaftScene::kH;

std::unique_ptr<render::Backend> soft() { return render::soft::createSoftBackend({1, 64, false}); }

// The previous tests' scenes: open sky, or a small tree right over the sun.
std::vector<Card> treeOverSun(bool tree) {
    if (!tree) return {};
    return {{-1.5f, -1.0f, 1.5f, 3.0f, 8.0f}};
}

const render::PassTiming* findPass(const std::vector<render::PassTiming>& timings, const std::string& name) {
    for (const render::PassTiming& t : timings)
        if (t.pass == name) return &t;
    return nullptr;
}

float added(const render::Readback& with, const render::Readback& without, int x, int y) {
    return (with.at(x, y, 0) - without.at(x, y, 0)) + (with.at(x, y, 1) - without.at(x, y, 1)) +
           (with.at(x, y, 2) - without.at(x, y, 2));
}

TEST(LightShafts, FoliageOverTheSunBlocksTheShafts) {
    const glm::vec3 sun = kSunAhead;
    ShaftScene open(soft(), treeOverSun(false)), blocked(soft(), treeOverSun(true));
    lightshafts::LightShaftFeature a(*open.backend), b(*blocked.backend);
    const render::Readback openWith = open.render(&a, sun), openWithout = open.render(nullptr, sun);
    const render::Readback blockedWith = blocked.render(&b, sun), blockedWithout = blocked.render(nullptr, sun);
    ASSERT_TRUE(a.ranLastFrame());
    const int sx = int(a.sunPixel().x), sy = int(a.sunPixel().y);
    ASSERT_GE(sx, 0);
    ASSERT_LT(sx, kW);
    ASSERT_GE(sy, 0);
    ASSERT_LT(sy, kH);
    EXPECT_GT(added(openWith, openWithout, sx, sy), 0.1f) << "open sky at the sun adds light";
    EXPECT_EQ(added(blockedWith, blockedWithout, sx, sy), 0.0f) << "the tree over the sun lets light through";
    // Below the tree (on the hill) the blocked frame gets less light than the open one.
    EXPECT_LT(added(blockedWith, blockedWithout, sx, kH - 4), added(openWith, openWithout, sx, kH - 4));
}

TEST(LightShafts, OffWhenTheSunIsBehindOrTheModuleIsOff) {
    ShaftScene s(soft(), treeOverSun(false));
    lightshafts::LightShaftFeature f(*s.backend);
    s.backend->takeTimings();
    const render::Readback behind = s.render(&f, {0.0f, 0.3f, -1.0f});
    EXPECT_FALSE(f.ranLastFrame());
    for (const auto& t : s.backend->takeTimings()) EXPECT_EQ(t.pass.find("light shafts"), std::string::npos) << t.pass;
    EXPECT_EQ(behind.values, s.render(nullptr, {0.0f, 0.3f, -1.0f}).values);
    s.render(&f, {0.0f, 0.15f, 1.0f});
    const auto timings = s.backend->takeTimings();
    EXPECT_TRUE(std::any_of(timings.begin(), timings.end(), [](const auto& t) { return t.pass == "light shafts"; }));
}

// The sun is fully occluded when no sky is left within its glow: the pass is skipped (its
// draw does not run) and the frame is bit-identical to running it, which adds exactly 0.
TEST(LightShafts, SkippedWhenTheSunIsFullyOccluded) {
    ShaftScene s(soft(), living::testing::canopyOverTheSun());
    lightshafts::LightShaftFeature probed(*s.backend);
    lightshafts::LightShaftOptions always;
    always.skipWhenSunHidden = false;
    lightshafts::LightShaftFeature forced(*s.backend, always);
    s.backend->takeTimings();
    const render::Readback skipped = s.render(&probed, kSunAhead);
    const auto timings = s.backend->takeTimings();
    ASSERT_TRUE(probed.ranLastFrame());
    EXPECT_FALSE(probed.sunVisible());
    const render::PassTiming* shafts = findPass(timings, "light shafts");
    ASSERT_NE(shafts, nullptr);
    EXPECT_TRUE(shafts->skipped);
    ASSERT_NE(findPass(timings, "light shafts: sun visibility"), nullptr);
    // Sky (the reverse-Z clear, 0) shows elsewhere, so a probe of the whole frame would not skip.
    const render::Readback depth = s.backend->readback(s.frame.opaque.depth());
    EXPECT_EQ(depth.at(1, 1, 0), 0.0f);
    EXPECT_EQ(depth.at(kW - 2, 1, 0), 0.0f);
    EXPECT_GT(depth.at(kW / 2, kH / 2, 0), 0.0f);
    const render::Readback without = s.render(nullptr, kSunAhead);
    const render::Readback run = s.render(&forced, kSunAhead);
    EXPECT_FALSE(findPass(s.backend->takeTimings(), "light shafts")->skipped);
    EXPECT_EQ(skipped.values, run.values) << "skipping changed the frame";
    EXPECT_EQ(skipped.values, without.values);
}

// One column of sky through the canopy at the sun is enough: the pass runs and adds light.
TEST(LightShafts, RunsWhenASlitOfSkyShowsAtTheSun) {
    ShaftScene s(soft(), living::testing::canopyWithAGap());
    lightshafts::LightShaftFeature f(*s.backend);
    s.backend->takeTimings();
    const render::Readback with = s.render(&f, kSunAhead);
    EXPECT_TRUE(f.sunVisible());
    EXPECT_FALSE(findPass(s.backend->takeTimings(), "light shafts")->skipped);
    const render::Readback without = s.render(nullptr, kSunAhead);
    float sum = 0.0f;
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) sum += added(with, without, x, y);
    EXPECT_GT(sum, 0.05f) << "the slit casts a shaft";
}

// Skipping is exact, never a guess: canopies with a small hole at random places around the
// rim of the glow, where a texel half in the glow could be missed, give the same bits with
// the probe as with the pass forced on, and both outcomes occur.
TEST(LightShafts, SkippingNeverChangesTheFrame) {
    std::mt19937 random(7);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    const float pixelsPerUnit = float(kH) / (2.0f * std::tan(0.5f) * 8.0f);  // at z = 8
    const float glow = 0.3f * float(kH);
    int skips = 0, runs = 0;
    for (int i = 0; i < 24; ++i) {
        const float angle = 6.2831853f * unit(random);
        const float distance = (glow - 2.0f + 4.0f * unit(random)) / pixelsPerUnit;
        const float half = (0.05f + 0.1f * unit(random)) / 2.0f;
        const float hx = distance * std::cos(angle), hy = 1.2f + distance * std::sin(angle);  // the sun is at y 1.2
        const std::vector<Card> canopy = {{-4.0f, -2.8f, hx - half, 5.2f, 8.0f},
                                          {hx + half, -2.8f, 4.0f, 5.2f, 8.0f},
                                          {hx - half, -2.8f, hx + half, hy - half, 8.0f},
                                          {hx - half, hy + half, hx + half, 5.2f, 8.0f}};
        ShaftScene s(soft(), canopy);
        lightshafts::LightShaftFeature probed(*s.backend);
        lightshafts::LightShaftOptions always;
        always.skipWhenSunHidden = false;
        lightshafts::LightShaftFeature forced(*s.backend, always);
        const render::Readback a = s.render(&probed, kSunAhead);
        (probed.sunVisible() ? runs : skips) += 1;
        ASSERT_EQ(a.values, s.render(&forced, kSunAhead).values) << "hole " << i << " at " << hx << "," << hy;
    }
    EXPECT_GT(skips, 0);
    EXPECT_GT(runs, 0);
}

// A sun in front of the camera whose glow misses the frame casts nothing: no pass at all.
TEST(LightShafts, OffWhenTheGlowMissesTheFrame) {
    ShaftScene s(soft(), treeOverSun(false));
    lightshafts::LightShaftFeature f(*s.backend);
    s.backend->takeTimings();
    s.render(&f, glm::normalize(glm::vec3(1.0f, 0.15f, 0.6f)));  // far to the side, in front
    EXPECT_FALSE(f.ranLastFrame());
    const float glow = 0.3f * kH + 1.0f;
    EXPECT_TRUE(f.sunPixel().x < -glow || f.sunPixel().x > float(kW) + glow) << f.sunPixel().x;
    for (const auto& t : s.backend->takeTimings()) EXPECT_EQ(t.pass.find("light shafts"), std::string::npos) << t.pass;
}

TEST(LightShafts, DeterministicAndBadInputRefused) {
    ShaftScene s(soft(), treeOverSun(true));
    lightshafts::LightShaftFeature f(*s.backend);
    const glm::vec3 sun{0.2f, 0.3f, 1.0f};
    EXPECT_EQ(s.render(&f, sun).values, s.render(&f, sun).values);
    lightshafts::LightShaftOptions o;
    o.samples = 0;
    EXPECT_THROW(lightshafts::LightShaftFeature(*s.backend, o), Error);
    o = {};
    o.intensity = std::numeric_limits<float>::quiet_NaN();
    EXPECT_THROW(lightshafts::LightShaftFeature(*s.backend, o), Error);
    o = {};
    o.decay = 1.5f;
    try {
        lightshafts::LightShaftFeature g(*s.backend, o);
        FAIL();
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("decay"), std::string::npos);
    }
}

// The module's program on the backend (Backend::createProgram): it reads one float of depth
// per texel, and a draw with another module's parameters is refused.
TEST(LightShafts, ProgramRefusesBadDepthAndForeignParameters) {
    auto b = render::soft::createSoftBackend({});
    auto texture = [&](render::Format format) {
        render::TextureDesc t;
        t.name = "t";
        t.width = t.height = 8;
        t.format = format;
        t.usage = render::UsageSampled | render::UsageRenderTarget;
        return b->createTexture(t);
    };
    const render::TextureHandle target = texture(render::Format::RGBA32F);
    const render::ProgramHandle program = b->createProgram(lightshafts::lightShaftProgram());
    render::PipelineDesc p;
    p.name = "shafts";
    p.program = program;
    const render::PipelineHandle pipeline = b->createPipeline(p);
    auto draw = [&](render::DrawParams params) {
        render::PassDesc pass;
        pass.name = "pass";
        pass.color[0] = {target, render::LoadOp::Clear};
        b->beginPass(pass);
        render::DrawDesc d;
        d.pipeline = pipeline;
        d.params = params;
        try {
            b->draw(d);
        } catch (...) {
            b->endPass();
            throw;
        }
        b->endPass();
    };
    lightshafts::LightShaftParams shafts;
    shafts.depth = texture(render::Format::RGBA16F);
    ssam::testing::expectError([&] { draw(shafts); }, "light-shaft depth is RGBA16F, not D32F or R32F");
    ssam::testing::expectError([&] { draw(render::FlatParams{}); }, "parameters do not match program LightShafts");
    shafts.depth = texture(render::Format::R32F);
    EXPECT_NO_THROW(draw(shafts));
    b->destroy(pipeline);
    b->destroy(program);
}

}  // namespace
