// SPDX-License-Identifier: MIT
// The living-scene registry: racer's table holds the modules of modules/CMakeLists.txt in
// frame order with their flags and defaults; the tests' table is racer's followed by the
// test-only modules; racer's flags come from the table; and every module of the tests' table
// renders in racer's frame, made through the living scene from its row alone.
#include <gtest/gtest.h>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

#include "engine/render/soft/soft_backend.hpp"
#include "frame_renderer.hpp"
#include "living_scene.hpp"
#include "module_bench.hpp"
#include "racer_options.hpp"
#include "test_feature_modules.hpp"

namespace racer::testing {
namespace {

std::vector<std::string> namesOf(std::span<const engine::scene::FeatureModule> table) {
    std::vector<std::string> names;
    for (const engine::scene::FeatureModule& m : table) names.emplace_back(m.name);
    return names;
}

TEST(ModuleRegistry, RacerHasTheLivingSceneModulesInFrameOrderAllOnByDefault) {
    EXPECT_EQ(namesOf(featureModules()),
              (std::vector<std::string>{"wind", "grass", "water", "particles", "lightshafts"}));
    for (const engine::scene::FeatureModule& m : featureModules()) {
        EXPECT_EQ(std::string(m.flag), "--no-" + std::string(m.name));
        EXPECT_TRUE(m.enabledByDefault) << m.name;
        EXPECT_NE(m.make, nullptr) << m.name << " is built by default";
    }
}

TEST(ModuleRegistry, TheTestsTableIsRacersFollowedByTheTestOnlyModules) {
    const auto racer = featureModules(), tests = ssam::testing::featureModules();
    ASSERT_GT(tests.size(), racer.size());
    for (std::size_t i = 0; i < racer.size(); ++i) {
        EXPECT_EQ(std::string(tests[i].name), racer[i].name);
        EXPECT_EQ(std::string(tests[i].flag), racer[i].flag);
        EXPECT_EQ(tests[i].enabledByDefault, racer[i].enabledByDefault);
        EXPECT_EQ(tests[i].make, racer[i].make);
    }
}

TEST(ModuleRegistry, RacersFlagsFlipTheDefaults) {
    CLI::App app;
    Options o;
    addOptions(app, o);
    const char* argv[] = {"racer", "--no-grass", "--no-lightshafts"};
    app.parse(3, argv);
    const std::map<std::string, bool> enabled = enabledModules(o);
    EXPECT_EQ(enabled,
              (std::map<std::string, bool>{
                  {"grass", false}, {"lightshafts", false}, {"particles", true}, {"water", true}, {"wind", true}}));
}

class RegisteredModule : public ::testing::TestWithParam<const engine::scene::FeatureModule*> {};

// Alone in racer's frame, through LivingScene with the tests' table: made, its systems run,
// its passes in the frame graph.
TEST_P(RegisteredModule, RendersInRacersFrameFromItsRowAlone) {
    const engine::scene::FeatureModule& module = *GetParam();
    const auto soft = engine::render::soft::createSoftBackend({1, 64, false});
    RacingScene scene(*soft, SceneOptions{defaultContentDir(), 1});
    RendererOptions options;
    options.width = ModuleBench::kWidth;
    options.height = ModuleBench::kHeight;
    options.sun = scene.sun();
    FrameRenderer renderer(*soft, scene.library(), options);
    LivingSceneOptions lo;
    lo.modules = ssam::testing::featureModules();
    lo.enabled = onlyModules(lo.modules, {module.name});
    lo.track = &scene.track();
    LivingScene living(scene.registry(), scene.library(), lo);
    ASSERT_EQ(living.names().size(), 1u) << "exactly the module asked for";
    EXPECT_TRUE(living.missing().empty());
    renderer.setLivingScene(&living);
    for (int i = 0; i < 3; ++i) {
        const float time = float(i) * ModuleBench::kDt;
        scene.update(ModuleBench::kDt);
        const CameraView view = cameraView(CameraMode::Chase, scene, time,
                                           float(ModuleBench::kWidth) / float(ModuleBench::kHeight), FreeCamera{});
        living.update(time, ModuleBench::kDt, view);
        renderer.render(engine::scene::extractDrawLists(scene.registry(), scene.library(), view.viewProj, view.eye),
                        view);
    }
    // Its passes are in the frame's graph (drawn, or marked empty where it had nothing to
    // draw); wind adds none, having systems only.
    std::ostringstream graph;
    renderer.dumpGraph(graph);
    if (module.name != std::string("wind")) {
        EXPECT_NE(graph.str().find(living.names().front()), std::string::npos) << graph.str();
    }
}

INSTANTIATE_TEST_SUITE_P(Registered, RegisteredModule,
                         ::testing::ValuesIn(builtModules(ssam::testing::featureModules())), ModuleName{});

}  // namespace
}  // namespace racer::testing
