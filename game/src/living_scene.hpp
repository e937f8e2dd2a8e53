// SPDX-License-Identifier: MIT
#pragma once
// The living scene: the enabled modules' features in frame order, their systems in one ECS
// scheduler, run each frame after the simulation step and before extraction. The modules,
// their order and their defaults are the registry's (racer_feature_modules.hpp, generated from
// the ssam_module() lines in modules/CMakeLists.txt), so this file names none of them. A
// module left out of the build (-DSSAM_MODULE_<NAME>=OFF) or switched off by its flag
// (--no-wind ...) is simply not in the list: only its feature goes.
#include <initializer_list>
#include <map>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "camera_rig.hpp"
#include "engine/core/ecs/scheduler.hpp"
#include "engine/core/non_copyable.hpp"
#include "engine/scene/feature_module.hpp"
#include "engine/scene/frame_feature.hpp"
#include "racer_feature_modules.hpp"

namespace racer {

class Track;

struct LivingSceneOptions {
    // Which modules there are, in frame order: racer's own registry unless a test brings one
    // with modules of its own.
    std::span<const engine::scene::FeatureModule> modules = featureModules();
    // On or off by module name; a module not named here takes its default.
    std::map<std::string, bool> enabled{};
    std::uint32_t seed = 1;
    const Track* track = nullptr;  // its verge is where low plants grow (none: no verge)
};

// `modules` with every one switched off but those named in `on`, for tests that want a few.
std::map<std::string, bool> onlyModules(std::span<const engine::scene::FeatureModule> modules,
                                        std::initializer_list<const char*> on);

class LivingScene : engine::NonCopyable {
public:
    LivingScene(engine::ecs::Registry& registry, const engine::scene::MeshLibrary& library,
                const LivingSceneOptions& options);
    ~LivingScene();

    // The features' systems for this frame (wind deformation, water ripples), seen from
    // `camera`; call after the simulation step, before extraction. `motionVectors`: the frame
    // reads motion vectors (FrameRenderer::needsMotionVectors), so the wind makes its motion copies.
    void update(float time, float dt, const CameraView& camera, bool motionVectors = false);
    // Every feature's passes, in frame order, onto `frame`'s colour and depth, whose latest
    // versions in `graph` are `targets` (its time is the last update's). Returns the
    // versions the last feature left.
    engine::render::ColorDepth addPasses(engine::render::FrameGraph& graph, const engine::scene::FeatureFrame& frame,
                                         engine::render::ColorDepth targets);

    // Names of the enabled features, in frame order ("wind", "grass", ...).
    std::vector<std::string> names() const;
    // Modules asked for but not in this build.
    const std::vector<std::string>& missing() const { return missing_; }

private:
    engine::ecs::Registry& registry_;
    engine::ecs::Scheduler scheduler_;
    std::vector<std::unique_ptr<engine::scene::Feature>> features_;
    std::vector<std::string> missing_;
    float time_ = 0.0f;
};

}  // namespace racer
