// SPDX-License-Identifier: MIT
#pragma once
// The tint module's row in the living-scene registry (modules/feature_table.cmake): the
// factory the generated table points to.
#include <memory>

#include "engine/scene/feature_module.hpp"

namespace tint {

// The frame's colour multiplied by a warm tint (kTint), after every other feature.
std::unique_ptr<engine::scene::Feature> makeFeature(const engine::scene::FeatureContext& context);

inline constexpr float kTint[3] = {1.0f, 0.5f, 0.25f};

}  // namespace tint
