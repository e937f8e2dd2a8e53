// SPDX-License-Identifier: MIT
#include "tint/tint_module.hpp"

#include "tint_feature.hpp"

namespace tint {

std::unique_ptr<engine::scene::Feature> makeFeature(const engine::scene::FeatureContext& context) {
    return std::make_unique<TintFeature>(context.library.backend(), glm::vec3(kTint[0], kTint[1], kTint[2]));
}

}  // namespace tint
