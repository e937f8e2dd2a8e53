// SPDX-License-Identifier: MIT
#pragma once
// The grass module's row in the living-scene registry (modules/feature_table.cmake): the
// factory the generated table points to.
#include <memory>

#include "engine/scene/feature_module.hpp"

namespace grass {

// Grass cards on the context's verge; null when the scene has none (no road).
std::unique_ptr<engine::scene::Feature> makeFeature(const engine::scene::FeatureContext& context);

}  // namespace grass
