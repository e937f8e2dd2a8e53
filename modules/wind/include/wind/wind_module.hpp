// SPDX-License-Identifier: MIT
#pragma once
// The wind module's row in the living-scene registry (modules/feature_table.cmake): the
// factory the generated table points to.
#include <memory>

#include "engine/scene/feature_module.hpp"

namespace wind {

// The wind over the context's scene: every foliage plant in its registry sways, colliders push.
std::unique_ptr<engine::scene::Feature> makeFeature(const engine::scene::FeatureContext& context);

}  // namespace wind
