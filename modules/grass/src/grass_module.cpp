// SPDX-License-Identifier: MIT
#include "grass/grass_module.hpp"

#include "grass/grass_feature.hpp"

namespace grass {

std::unique_ptr<engine::scene::Feature> makeFeature(const engine::scene::FeatureContext& context) {
    if (!context.plantingSpots) return nullptr;  // nowhere to grow
    std::vector<Tuft> tufts;
    for (const engine::scene::GroundSpot& spot : context.plantingSpots())
        tufts.push_back({spot.root, spot.yaw, spot.scale});
    return std::make_unique<GrassFeature>(context.library.backend(), std::move(tufts));
}

}  // namespace grass
