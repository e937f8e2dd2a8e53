// SPDX-License-Identifier: MIT
#pragma once
// The living scene: the enabled modules' features in frame order (grass ->
// water -> particles -> light shafts after the foliage technique; wind has systems only),
// their systems in one ECS scheduler, run each frame after the simulation step and before
// extraction. A module left out of the build (-DSSAM_MODULE_<NAME>=OFF) or switched off by
// its flag (--no-wind ...) is simply not in the list: only its feature goes.
#include <memory>
#include <string>
#include <vector>

#include "camera_rig.hpp"
#include "engine/core/ecs/scheduler.hpp"
#include "engine/scene/frame_feature.hpp"

namespace racer {

class Track;

struct LivingSceneOptions {
    bool wind = true;
    bool water = true;
    bool grass = true;
    bool particles = true;
    bool lightshafts = true;
    std::uint32_t seed = 1;
    const Track* track = nullptr;  // grass grows in a band along it (none: no grass)
};

class LivingScene {
public:
    LivingScene(engine::ecs::Registry& registry, const engine::scene::MeshLibrary& library,
                const LivingSceneOptions& options);
    ~LivingScene();
    LivingScene(const LivingScene&) = delete;
    LivingScene& operator=(const LivingScene&) = delete;

    // The features' systems for this frame (wind deformation, water ripples), seen from
    // `camera`; call after the simulation step, before extraction.
    void update(float time, float dt, const CameraView& camera);
    // Every feature's passes, in frame order, onto `frame`'s colour and depth, whose latest
    // versions in `graph` are `targets` (its time is the last update's). Returns the
    // versions the last feature left.
    engine::render::ColorDepth addPasses(engine::render::FrameGraph& graph, const engine::scene::FeatureFrame& frame,
                                         engine::render::ColorDepth targets);

    // Names of the enabled features, in frame order ("wind", "water", ...).
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
