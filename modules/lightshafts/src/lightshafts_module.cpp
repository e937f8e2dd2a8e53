// SPDX-License-Identifier: MIT
#include "lightshafts/lightshafts_module.hpp"

#include "lightshafts/light_shaft_feature.hpp"

namespace lightshafts {

std::unique_ptr<engine::scene::Feature> makeFeature(const engine::scene::FeatureContext& context) {
    return std::make_unique<LightShaftFeature>(context.library.backend());
}

}  // namespace lightshafts
