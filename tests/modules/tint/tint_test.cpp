// SPDX-License-Identifier: MIT
// modules built only in the tests: the tint, made through the tests' registry like any
// module, multiplies the frame's colour and leaves its alpha.
#include <gtest/gtest.h>

#include <string>

#include "engine/core/ecs/registry.hpp"
#include "engine/render/pass_scope.hpp"
#include "engine/render/soft/soft_backend.hpp"
#include "engine/scene/mesh_library.hpp"
#include "test_feature_modules.hpp"
#include "tint/tint_module.hpp"
#include "run_feature.hpp"

namespace {

using namespace engine;

const scene::FeatureModule* registered(const char* name) {
    for (const scene::FeatureModule& m : ssam::testing::featureModules())
        if (std::string(m.name) == name) return &m;
    return nullptr;
}

TEST(Tint, IsInTheTestsRegistryOffByDefault) {
    const scene::FeatureModule* tint = registered("tint");
    ASSERT_NE(tint, nullptr);
    EXPECT_EQ(std::string(tint->flag), "--tint");
    EXPECT_FALSE(tint->enabledByDefault);
    EXPECT_NE(tint->make, nullptr);
    // After racer's modules: registered later, so its pass comes last.
    EXPECT_EQ(std::string(ssam::testing::featureModules().back().name), "tint");
}

TEST(Tint, MultipliesTheFrameColourThroughTheRegistry) {
    constexpr int kW = 16, kH = 8;
    const auto backend = render::soft::createSoftBackend({1, 64, false});
    ecs::Registry registry;
    scene::MeshLibrary library(*backend);
    const scene::FeatureModule* tint = registered("tint");
    ASSERT_NE(tint, nullptr);
    std::unique_ptr<scene::Feature> feature = tint->make({registry, library, 1, {}});
    ASSERT_NE(feature, nullptr);
    EXPECT_EQ(feature->name(), "tint");

    const render::TextureHandle color =
        backend->createTexture(render::renderTargetDesc("frame", kW, kH, render::Format::RGBA32F));
    const render::TextureHandle depth =
        backend->createTexture(render::renderTargetDesc("depth", kW, kH, render::Format::D32F));
    render::PassDesc clear;
    clear.name = "frame";
    clear.color[0] = {color, render::LoadOp::Clear, {0.8f, 0.6f, 0.4f, 0.7f}};
    render::PassScope scope(*backend, clear);
    scope.end();

    const scene::DrawLists lists;
    const scene::FeatureFrame frame{
        *backend,        library,         lists,           color,           depth, kW,   kH,
        glm::mat4(1.0f), glm::mat4(1.0f), glm::mat4(1.0f), glm::vec3(0.0f), {},    0.0f, render::CompareFunc::Less};
    test_support::runFeatures({feature.get()}, frame);
    const render::Readback r = backend->readback(color);
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) {
            EXPECT_FLOAT_EQ(r.at(x, y, 0), 0.8f * tint::kTint[0]);
            EXPECT_FLOAT_EQ(r.at(x, y, 1), 0.6f * tint::kTint[1]);
            EXPECT_FLOAT_EQ(r.at(x, y, 2), 0.4f * tint::kTint[2]);
            EXPECT_FLOAT_EQ(r.at(x, y, 3), 0.7f);
        }
    feature.reset();
    backend->destroy(color);
    backend->destroy(depth);
}

}  // namespace
