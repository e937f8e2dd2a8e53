// SPDX-License-Identifier: MIT
#include "particles/particles_module.hpp"

#include <vector>

#include "engine/scene/components.hpp"
#include "particles/particle_feature.hpp"

namespace particles {

std::unique_ptr<engine::scene::Feature> makeFeature(const engine::scene::FeatureContext& context) {
    // Whatever collides (the car) raises dust and spray from its wheels.
    std::vector<engine::ecs::Entity> colliders;
    context.registry.view<const engine::scene::Collider>().each(
        [&](engine::ecs::Entity e, const engine::scene::Collider&) { colliders.push_back(e); });
    for (engine::ecs::Entity e : colliders)
        if (!context.registry.has<WheelEmitter>(e)) context.registry.add<WheelEmitter>(e);
    return std::make_unique<ParticleFeature>(context.library.backend(), ParticleOptions{}, context.seed);
}

}  // namespace particles
