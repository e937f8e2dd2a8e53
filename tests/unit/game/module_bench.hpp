// SPDX-License-Identifier: MIT
#pragma once
// One registered living-scene module on its own in the racing scene, for the registry's
// tests: the scene (on a FailingBackend that fails nothing until told), a frame's colour and
// depth targets, and two views one step after the start: the chase camera (grass, dust, light
// shafts) and the free camera's overview (the pools). firstFrame() makes the module's feature
// through its registry row and runs its first frame from each view: systems, then passes.
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "camera_rig.hpp"
#include "content_dir.hpp"
#include "engine/core/ecs/scheduler.hpp"
#include "engine/render/pass_scope.hpp"
#include "engine/scene/draw_lists.hpp"
#include "engine/scene/feature_module.hpp"
#include "failing_backend.hpp"  // tests/support
#include "racing_scene.hpp"
#include "verge.hpp"
#include "run_feature.hpp"

namespace racer::testing {

class ModuleBench {
public:
    static constexpr int kWidth = 96, kHeight = 54;
    static constexpr float kDt = 1.0f / 30.0f;

    explicit ModuleBench(engine::render::Backend& inner)
        : backend(inner), scene_(backend, SceneOptions{defaultContentDir(), 1}), verge_(vergeAlong(scene_.track(), 1)) {
        using namespace engine::render;
        color_ = backend.createTexture(renderTargetDesc("frame", kWidth, kHeight, Format::RGBA8_UNORM), nullptr);
        depth_ = backend.createTexture(renderTargetDesc("depth", kWidth, kHeight, Format::D32F), nullptr);
        scene_.update(kDt);  // the car drives off: its wheels raise dust
        for (CameraMode mode : {CameraMode::Chase, CameraMode::Free})
            views_.push_back(cameraView(mode, scene_, kDt, float(kWidth) / float(kHeight), FreeCamera{}));
    }
    ~ModuleBench() {
        backend.destroy(color_);
        backend.destroy(depth_);
    }
    ModuleBench(const ModuleBench&) = delete;
    ModuleBench& operator=(const ModuleBench&) = delete;

    // Makes `module`'s feature and runs its first frame from each view; the feature is gone
    // when it returns or throws.
    void firstFrame(const engine::scene::FeatureModule& module) {
        using namespace engine::render;
        const engine::scene::FeatureContext context{scene_.registry(), scene_.library(), 1, [this] { return verge_; }};
        const std::unique_ptr<engine::scene::Feature> feature = module.make(context);
        if (!feature) return;
        engine::ecs::Scheduler scheduler;  // holds the feature's systems: destroyed first
        feature->registerSystems(scheduler);
        for (const CameraView& view : views_) {
            feature->beginFrame({kDt, kDt, view.eye, view.viewProj});
            scheduler.run(scene_.registry());
            const engine::scene::DrawLists lists =
                engine::scene::extractDrawLists(scene_.registry(), scene_.library(), view.viewProj, view.eye);
            PassDesc clear;
            clear.name = "sky";
            clear.color[0] = {color_, LoadOp::Clear, {0.5f, 0.6f, 0.8f, 1.0f}};
            clear.depth = {depth_, LoadOp::Clear, 0.0f};  // reverse-Z: 0 is the far plane
            PassScope(backend, clear).end();
            const engine::scene::FeatureFrame frame{
                backend,   scene_.library(), lists,         color_,   depth_,       kWidth, kHeight,
                view.view, view.projection,  view.viewProj, view.eye, scene_.sun(), kDt,    CompareFunc::Greater};
            test_support::runFeatures({feature.get()}, frame);
        }
    }

    // Whether the backend still runs a pass: clears the frame to green and reads green back.
    bool usable() {
        using namespace engine::render;
        PassDesc green;
        green.name = "usable";
        green.color[0] = {color_, LoadOp::Clear, {0.0f, 1.0f, 0.0f, 1.0f}};
        PassScope(backend, green).end();
        const Readback r = backend.readback(color_);
        return r.at(kWidth / 2, kHeight / 2, 0) == 0.0f && r.at(kWidth / 2, kHeight / 2, 1) == 1.0f;
    }

    ssam::testing::FailingBackend backend;

private:
    RacingScene scene_;
    std::vector<engine::scene::GroundSpot> verge_;
    engine::render::TextureHandle color_, depth_;
    std::vector<CameraView> views_;
};

// The modules of `table` that are built, for INSTANTIATE_TEST_SUITE_P, named after them.
inline std::vector<const engine::scene::FeatureModule*> builtModules(
    std::span<const engine::scene::FeatureModule> table) {
    std::vector<const engine::scene::FeatureModule*> built;
    for (const engine::scene::FeatureModule& m : table)
        if (m.make) built.push_back(&m);
    return built;
}
struct ModuleName {
    std::string operator()(const ::testing::TestParamInfo<const engine::scene::FeatureModule*>& info) const {
        return info.param->name;
    }
};

}  // namespace racer::testing
