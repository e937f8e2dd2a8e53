// SPDX-License-Identifier: MIT
#pragma once
// The racing scene's ground as the player's car feels it (car_driver.hpp): the ground mesh's
// height (ground.hpp), and on the road the road's surface, level across at the centre line's
// height (Track::buildRoad), which the ground stays below.
#include <glm/glm.hpp>

#include "ground.hpp"
#include "track.hpp"

namespace racer {

// The distance along `track` of the centre-line point nearest to (x, z) (horizontally):
// sampled every 2 m over the whole lap, then refined to 0.1 m. Used per frame and when the
// autopilot takes the car back.
float nearestTrackDistance(const Track& track, float x, float z);

// The height of whatever the car stands on at (x, z): the road's surface within its width,
// else the ground; never below the ground.
float groundHeight(const Track& track, const Ground& ground, float x, float z);

}  // namespace racer
