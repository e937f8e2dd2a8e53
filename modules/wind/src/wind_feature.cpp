// SPDX-License-Identifier: MIT
#include "wind/wind_feature.hpp"

namespace wind {

WindFeature::WindFeature(engine::ecs::Registry& registry, const engine::scene::MeshLibrary& library, std::uint32_t seed)
    : system_(library) {
    if (registry.view<const Wind>().sizeHint() == 0) registry.add<Wind>(registry.create());
    system_.attach(registry, seed);
}

void WindFeature::registerSystems(engine::ecs::Scheduler& scheduler) {
    scheduler.add(engine::ecs::phase::deformation, "wind",
                  [this](engine::ecs::Registry& registry, engine::ecs::CommandBuffer&) { system_.update(registry); });
}

void WindFeature::beginFrame(const engine::scene::SimulationFrame& frame) {
    system_.setFrame({frame.time, frame.dt, frame.eye, frame.viewProj, true, frame.motionVectors});
}

}  // namespace wind
