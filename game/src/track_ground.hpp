// SPDX-License-Identifier: MIT
#pragma once
// The racing scene's ground as the player's car feels it (car_driver.hpp): the terrain's
// height field, and on the road the road's surface, which lies a little above the terrain
// (track.cpp builds it 8 cm over the terrain at its edges).
#include <glm/glm.hpp>

#include "track.hpp"

namespace racer {

// The distance along `track` of the centre-line point nearest to (x, z) (horizontally):
// sampled every 2 m over the whole lap, then refined to 0.1 m. Used per frame and when the
// autopilot takes the car back.
float nearestTrackDistance(const Track& track, float x, float z);

// The height of whatever the car stands on at (x, z): the road's surface within its width
// (linear across it between its edges, as the road mesh is), else the terrain; never below
// the terrain.
float groundHeight(const Track& track, float x, float z);

}  // namespace racer
