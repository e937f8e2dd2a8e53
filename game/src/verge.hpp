// SPDX-License-Identifier: MIT
#pragma once
// The racing scene's verge: where low plants grow beside the track, for the living-scene
// modules that plant there (engine::scene::FeatureContext::verge).
#include <cstdint>
#include <vector>

#include "engine/scene/feature_module.hpp"

namespace racer {

class Track;

// Spots in a band on both sides of the track, clear of the road and its shoulders, every
// ~0.8 m along it, on the racing scene's ground (the same function of the track the scene
// builds): six rows a side, jittered by `seed`.
std::vector<engine::scene::GroundSpot> vergeAlong(const Track& track, std::uint32_t seed);

}  // namespace racer
