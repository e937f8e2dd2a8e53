// SPDX-License-Identifier: MIT
#pragma once
// The lightshafts module's row in the living-scene registry (modules/feature_table.cmake): the
// factory the generated table points to.
#include <memory>

#include "engine/scene/feature_module.hpp"

namespace lightshafts {

// Light shafts from the sun through the frame's depth.
std::unique_ptr<engine::scene::Feature> makeFeature(const engine::scene::FeatureContext& context);

}  // namespace lightshafts
