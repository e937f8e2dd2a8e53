// SPDX-License-Identifier: MIT
#include "wind/wind_module.hpp"

#include "wind/wind_feature.hpp"

namespace wind {

std::unique_ptr<engine::scene::Feature> makeFeature(const engine::scene::FeatureContext& context) {
    return std::make_unique<WindFeature>(context.registry, context.library, context.seed);
}

}  // namespace wind
