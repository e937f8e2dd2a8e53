// SPDX-License-Identifier: MIT
#pragma once
// The particles module's row in the living-scene registry (modules/feature_table.cmake): the
// factory the generated table points to.
#include <memory>

#include "engine/scene/feature_module.hpp"

namespace particles {

// Dust and spray from the wheels of every collider in the context's registry (the car).
std::unique_ptr<engine::scene::Feature> makeFeature(const engine::scene::FeatureContext& context);

}  // namespace particles
