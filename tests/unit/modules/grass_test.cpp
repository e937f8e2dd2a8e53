// SPDX-License-Identifier: MIT
// modules/grass: instanced alpha-tested cards, depth-tested against the foliage depth
// ([Hathaway 2010] §3.7), culled by distance, swaying deterministically.
#include <gtest/gtest.h>

#include "engine/core/error.hpp"
#include "engine/render/soft/soft_backend.hpp"
#include "grass/grass_feature.hpp"
#include "living_frame.hpp"

namespace {

using namespace engine;

constexpr int kW = 96, kH = 64;

struct GrassScene : living::testing::LivingScene {
    explicit GrassScene(bool tree) : LivingScene(kW, kH, {{0.0f, 1.0f, 0.0f}, {0.0f, 1.0f, 1.0f}, 1.0f}) {
        // A foliage card of full alpha (a "tree") 5 m ahead, covering the grass at 8 m.
        if (tree) addCard("tree", -1, -1, 1, 3, 5.0f, scene::SurfaceClass::Mask, {0.2f, 0.5f, 0.1f, 1.0f});
    }
};

std::vector<grass::Tuft> tuftAt(float z) { return {{{0.0f, 0.0f, z}, 0.4f, 1.0f}, {{0.15f, 0.0f, z}, 1.4f, 1.0f}}; }

TEST(Grass, BehindTheTreeHiddenInFrontVisible) {
    GrassScene bare(false), tree(true);
    const render::Readback nothing = bare.render(nullptr), treeOnly = tree.render(nullptr);

    grass::GrassFeature behindOpen(*bare.backend, tuftAt(8.0f));
    EXPECT_NE(bare.render(&behindOpen).values, nothing.values) << "the tuft at 8 m is not in view at all";
    EXPECT_GT(behindOpen.drawnLastFrame(), 0u);

    grass::GrassFeature behind(*tree.backend, tuftAt(8.0f));
    EXPECT_EQ(tree.render(&behind).values, treeOnly.values) << "grass behind the tree shows through it";

    GrassScene tree2(true);
    grass::GrassFeature front(*tree2.backend, tuftAt(3.0f));
    EXPECT_NE(tree2.render(&front).values, treeOnly.values) << "grass in front of the tree is missing";
}

TEST(Grass, OffOrFarMeansNoPass) {
    GrassScene s(true);
    s.backend->takeTimings();
    s.render(nullptr);
    for (const auto& t : s.backend->takeTimings()) EXPECT_NE(t.pass, "grass");
    grass::GrassFeature far(*s.backend, tuftAt(100.0f));  // beyond the 60 m draw distance
    s.render(&far);
    EXPECT_EQ(far.drawnLastFrame(), 0u);
    for (const auto& t : s.backend->takeTimings()) EXPECT_NE(t.pass, "grass");
    grass::GrassFeature near(*s.backend, tuftAt(3.0f));
    s.render(&near);
    const auto timings = s.backend->takeTimings();
    EXPECT_TRUE(std::any_of(timings.begin(), timings.end(), [](const auto& t) { return t.pass == "grass"; }));
}

TEST(Grass, DistanceCullingKeepsOnlyNearTufts) {
    std::vector<grass::Tuft> field;
    for (int i = 0; i < 200; ++i) field.push_back({{0.0f, 0.0f, 1.0f + float(i)}, 0.0f, 1.0f});
    grass::GrassOptions o;
    o.drawDistance = 40.0f;
    const glm::mat4 viewProj = living::testing::Camera{{0, 1, 0}, {0, 1, 1}, 1.0f}.projection(1.5f) *
                               living::testing::Camera{{0, 1, 0}, {0, 1, 1}, 1.0f}.view();
    const auto visible = grass::visibleTufts(field, o, {0, 1, 0}, viewProj, 0.0f);
    EXPECT_EQ(visible.size(), 39u);  // roots at 1..39 m (40 m is 40.01 m from an eye 1 m up)
    for (const auto& i : visible) EXPECT_LE(glm::length(glm::vec3(i.model[3]) - glm::vec3(0, 1, 0)), 40.0f);
}

TEST(Grass, SwayIsDeterministicAndMoves) {
    auto frameAt = [](float time) {
        GrassScene s(false);
        grass::GrassFeature g(*s.backend, tuftAt(3.0f));
        return s.render(&g, time);
    };
    EXPECT_EQ(frameAt(0.3f).values, frameAt(0.3f).values);
    EXPECT_NE(frameAt(0.3f).values, frameAt(0.9f).values);
}

TEST(Grass, BadInputIsRefused) {
    auto backend = render::soft::createSoftBackend({1, 64, false});
    grass::GrassOptions o;
    o.drawDistance = std::numeric_limits<float>::quiet_NaN();
    try {
        grass::GrassFeature g(*backend, {}, o);
        FAIL() << "NaN drawDistance accepted";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("GrassOptions.drawDistance"), std::string::npos);
    }
    o = {};
    o.height = -1.0f;
    EXPECT_THROW(grass::GrassFeature(*backend, {}, o), Error);
    o = {};
    o.alphaReference = 2.0f;
    EXPECT_THROW(grass::GrassFeature(*backend, {}, o), Error);
    o = {};
    o.windDirection = {0.0f, 1.0f, 0.0f};
    EXPECT_THROW(grass::GrassFeature(*backend, {}, o), Error);
    o = {};
    o.maxTufts = 3;
    try {
        grass::GrassFeature g(*backend, std::vector<grass::Tuft>(4), o);
        FAIL() << "too many tufts accepted";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("4 tufts exceed the limit of 3"), std::string::npos);
    }
    // A NaN root is never drawn (and never reaches the rasterizer).
    std::vector<grass::Tuft> bad{{{std::numeric_limits<float>::quiet_NaN(), 0.0f, 3.0f}, 0.0f, 1.0f}};
    EXPECT_TRUE(grass::visibleTufts(bad, {}, glm::vec3(0.0f), glm::mat4(1.0f), 0.0f).empty());
}

}  // namespace
