// SPDX-License-Identifier: MIT
#include "living_scene.hpp"

#include <algorithm>

#include "track.hpp"
#include "verge.hpp"

namespace racer {

std::map<std::string, bool> onlyModules(std::span<const engine::scene::FeatureModule> modules,
                                        std::initializer_list<const char*> on) {
    std::map<std::string, bool> enabled;
    for (const engine::scene::FeatureModule& m : modules)
        enabled[m.name] =
            std::any_of(on.begin(), on.end(), [&](const char* name) { return std::string(name) == m.name; });
    return enabled;
}

LivingScene::LivingScene(engine::ecs::Registry& registry, const engine::scene::MeshLibrary& library,
                         const LivingSceneOptions& options)
    : registry_(registry) {
    engine::scene::FeatureContext context{registry, library, options.seed, {}};
    if (options.track)
        context.plantingSpots = [track = options.track, seed = options.seed] { return vergeAlong(*track, seed); };
    for (const engine::scene::FeatureModule& module : options.modules) {
        const auto choice = options.enabled.find(module.name);
        if (!(choice != options.enabled.end() ? choice->second : module.enabledByDefault)) continue;
        if (!module.make) {
            missing_.emplace_back(module.name);
            continue;
        }
        if (std::unique_ptr<engine::scene::Feature> feature = module.make(context))
            features_.push_back(std::move(feature));
    }
    for (const auto& f : features_) f->registerSystems(scheduler_);
}

LivingScene::~LivingScene() = default;

void LivingScene::update(float time, float dt, const CameraView& camera, bool motionVectors) {
    time_ = time;
    for (const auto& f : features_) f->beginFrame({time, dt, camera.eye, camera.viewProj, motionVectors});
    scheduler_.run(registry_);
}

engine::render::ColorDepth LivingScene::addPasses(engine::render::FrameGraph& graph,
                                                  const engine::scene::FeatureFrame& frame,
                                                  engine::render::ColorDepth targets) {
    engine::scene::FeatureFrame timed = frame;
    timed.time = time_;
    for (const auto& f : features_) targets = f->addPasses(graph, timed, targets);
    return targets;
}

std::vector<std::string> LivingScene::names() const {
    std::vector<std::string> out;
    for (const auto& f : features_) out.emplace_back(f->name());
    return out;
}

}  // namespace racer
