// SPDX-License-Identifier: MIT
#include "water/water_module.hpp"

#include "water/water_feature.hpp"

namespace water {

std::unique_ptr<engine::scene::Feature> makeFeature(const engine::scene::FeatureContext& context) {
    return std::make_unique<WaterFeature>(context.library);
}

}  // namespace water
