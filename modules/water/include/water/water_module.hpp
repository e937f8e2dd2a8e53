// SPDX-License-Identifier: MIT
#pragma once
// The water module's row in the living-scene registry (modules/feature_table.cmake): the
// factory the generated table points to.
#include <memory>

#include "engine/scene/feature_module.hpp"

namespace water {

// The water pools of the context's scene, rippling.
std::unique_ptr<engine::scene::Feature> makeFeature(const engine::scene::FeatureContext& context);

}  // namespace water
