// modules/lightshafts: shafts from the sky the opaque + foliage depth leaves visible;
// foliage over the sun blocks them (seeds/000 §3.7); off behind the camera; bad input.
#include <gtest/gtest.h>

#include "engine/core/error.hpp"
#include "engine/render/soft/soft_backend.hpp"
#include "lightshafts/light_shaft_feature.hpp"
#include "living_frame.hpp"

namespace {

using namespace engine;
using living::testing::addRectangle;
using living::testing::place;

constexpr int kW = 64, kH = 48;

struct ShaftScene {
    std::unique_ptr<render::soft::SoftBackend> backend = render::soft::createSoftBackend({1, 64, false});
    scene::MeshLibrary library{*backend};
    ecs::Registry registry;
    living::testing::LivingFrame frame{*backend, library, kW, kH};
    // Looking at the sun: light comes from straight ahead and a little up.
    living::testing::Camera camera{{0, 0, 0}, {0.0f, 0.15f, 1.0f}, 1.0f};

    explicit ShaftScene(bool treeOverSun) {
        // Ground-ish wall at the bottom; optionally a foliage card right over the sun.
        place(registry, addRectangle(library, "hill", -30, -30, 30, -2, 20.0f, scene::SurfaceClass::Opaque,
                                     {0.3f, 0.4f, 0.2f, 1.0f}));
        if (treeOverSun)
            place(registry, addRectangle(library, "tree", -1.5f, -1.0f, 1.5f, 3.0f, 8.0f, scene::SurfaceClass::Mask,
                                         {0.2f, 0.5f, 0.1f, 1.0f}));
    }
    render::Readback render(scene::Feature* f, const glm::vec3& towardSun) {
        std::vector<scene::Feature*> features;
        if (f) features.push_back(f);
        sun = towardSun;
        return renderWithSun(features);
    }
    glm::vec3 sun{0, 0, 1};

private:
    render::Readback renderWithSun(const std::vector<scene::Feature*>& features) {
        struct SunOverride final : scene::Feature {
            std::vector<scene::Feature*> inner;
            glm::vec3 toward;
            std::string_view name() const override { return "sun"; }
            void render(const scene::FeatureFrame& f) override {
                scene::FeatureFrame g = f;
                g.sun.towardLight = toward;
                for (scene::Feature* i : inner) i->render(g);
            }
        } wrapper;
        wrapper.inner = features;
        wrapper.toward = sun;
        return frame.render(registry, camera, 0.0f, {&wrapper});
    }
};

float added(const render::Readback& with, const render::Readback& without, int x, int y) {
    return (with.at(x, y, 0) - without.at(x, y, 0)) + (with.at(x, y, 1) - without.at(x, y, 1)) +
           (with.at(x, y, 2) - without.at(x, y, 2));
}

TEST(LightShafts, FoliageOverTheSunBlocksTheShafts) {
    const glm::vec3 sun = glm::normalize(glm::vec3(0.0f, 0.15f, 1.0f));  // straight ahead
    ShaftScene open(false), blocked(true);
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
    ShaftScene s(false);
    lightshafts::LightShaftFeature f(*s.backend);
    s.backend->takeTimings();
    const render::Readback behind = s.render(&f, {0.0f, 0.3f, -1.0f});
    EXPECT_FALSE(f.ranLastFrame());
    for (const auto& t : s.backend->takeTimings()) EXPECT_NE(t.pass, "light shafts");
    EXPECT_EQ(behind.values, s.render(nullptr, {0.0f, 0.3f, -1.0f}).values);
    s.render(&f, {0.0f, 0.15f, 1.0f});
    const auto timings = s.backend->takeTimings();
    EXPECT_TRUE(std::any_of(timings.begin(), timings.end(), [](const auto& t) { return t.pass == "light shafts"; }));
}

TEST(LightShafts, DeterministicAndBadInputRefused) {
    ShaftScene s(true);
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

}  // namespace
