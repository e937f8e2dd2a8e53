// SPDX-License-Identifier: MIT
// modules/water: the pools are blended after SSAM and depth-tested against the foliage
// depth ([Hathaway 2010] §3.7): water behind a tree is hidden by it, water in front is not.
#include <gtest/gtest.h>

#include <cstring>

#include "engine/core/ecs/scheduler.hpp"
#include "engine/core/error.hpp"
#include "engine/render/soft/soft_backend.hpp"
#include "living_frame.hpp"
#include "water/water_feature.hpp"

namespace {

using namespace engine;
using scene::SurfaceClass;

constexpr int kW = 64, kH = 48;
const glm::vec4 kWater{0.1f, 0.3f, 0.9f, 0.6f};

struct WaterScene : living::testing::LivingScene {
    WaterScene() : LivingScene(kW, kH) {
        // An opaque-alpha foliage card (a "tree") in the middle, 5 m away.
        addCard("tree", -1, -1, 1, 1, 5.0f, SurfaceClass::Mask, {0.2f, 0.7f, 0.1f, 1.0f});
    }
    void addPools() {
        addCard("pool behind", -6, 0, 6, 3, 8.0f, SurfaceClass::Blend, kWater);
        addCard("pool in front", -6, -3, 6, -0.01f, 3.0f, SurfaceClass::Blend, kWater);
    }
};

glm::vec4 pixel(const render::Readback& r, int x, int y) {
    return {r.at(x, y, 0), r.at(x, y, 1), r.at(x, y, 2), r.at(x, y, 3)};
}

TEST(Water, HiddenBehindTheTreeVisibleInFront) {
    WaterScene dry;
    const render::Readback without = dry.frame.render(dry.registry, {}, 0.0f, {});

    WaterScene wet;
    wet.addPools();
    water::WaterFeature feature(wet.library);
    const render::Readback with = wet.frame.render(wet.registry, {}, 0.0f, {&feature});
    const auto timings = wet.backend->takeTimings();
    EXPECT_TRUE(std::any_of(timings.begin(), timings.end(), [](const auto& t) { return t.pass == "water"; }));

    EXPECT_EQ(pixel(with, 32, 18), pixel(without, 32, 18)) << "water behind the tree shows through it";
    EXPECT_NE(pixel(with, 32, 30), pixel(without, 32, 30)) << "water in front of the tree is missing";
    EXPECT_NE(pixel(with, 4, 18), pixel(without, 4, 18)) << "water behind, beside the tree, is missing";
    // Straight-alpha over: the pool's blue shows over the sky.
    EXPECT_GT(with.at(4, 18, 2), with.at(4, 18, 0));
}

TEST(Water, OffMeansNoPassAndUntouchedFrame) {
    WaterScene wet;
    wet.addPools();
    wet.backend->takeTimings();
    const render::Readback off = wet.frame.render(wet.registry, {}, 0.0f, {});
    for (const auto& t : wet.backend->takeTimings()) EXPECT_NE(t.pass, "water");
    WaterScene dry;
    const render::Readback none = dry.frame.render(dry.registry, {}, 0.0f, {});
    EXPECT_EQ(off.values, none.values);

    // No pool in view: the feature runs no pass.
    water::WaterFeature feature(dry.library);
    dry.backend->takeTimings();
    dry.frame.render(dry.registry, {}, 0.0f, {&feature});
    for (const auto& t : dry.backend->takeTimings()) EXPECT_NE(t.pass, "water");
}

TEST(Water, RipplesAnimateTheNormalsDeterministically) {
    auto run = [](float time) {
        WaterScene wet;
        wet.addPools();
        water::WaterFeature feature(wet.library);
        ecs::Scheduler scheduler;
        feature.registerSystems(scheduler);
        const living::testing::Camera camera;
        feature.beginFrame({time, 1.0f / 30.0f, camera.eye, camera.projection(float(kW) / kH) * camera.view()});
        scheduler.run(wet.registry);
        EXPECT_EQ(feature.ripplingSurfaces(), 2u);
        return wet.frame.render(wet.registry, camera, time, {&feature});
    };
    const render::Readback a = run(0.5f), b = run(0.5f), c = run(1.1f);
    EXPECT_EQ(a.values, b.values);
    EXPECT_NE(a.values, c.values);  // the highlight moved
    for (float v : c.values) EXPECT_TRUE(std::isfinite(v));
}

TEST(Water, BadRipplesAreRefused) {
    WaterScene s;
    water::Ripples r;
    r.amplitude = std::numeric_limits<float>::quiet_NaN();
    EXPECT_THROW(water::WaterFeature(s.library, r), Error);
    water::WaterFeature feature(s.library);
    r = {};
    r.wavelength = 0.0f;
    try {
        feature.setRipples(r);
        FAIL();
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("Ripples.wavelength"), std::string::npos);
    }
    r = {};
    r.speed = -2.0f;
    EXPECT_THROW(feature.setRipples(r), Error);
    // A zero-length normal stays finite.
    std::vector<render::Vertex> rest(1), out(1);
    rest[0].normal = glm::vec3(0.0f);
    water::rippleNormals(rest, out, {}, 3.0f);
    for (int c = 0; c < 3; ++c) EXPECT_TRUE(std::isfinite(out[0].normal[c]));
}

}  // namespace
