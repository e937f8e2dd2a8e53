// SPDX-License-Identifier: MIT
// The racing scene's ground under the player's car (game/src/track_ground.hpp).
#include <cmath>
#include <gtest/gtest.h>

#include "track_ground.hpp"

namespace racer {
namespace {

TEST(TrackGround, NearestTrackDistanceFindsTheCentreLine) {
    const Track track(1);
    for (float d : {0.5f, 100.0f, 733.3f, track.length() - 3.0f}) {
        const glm::vec3 p = track.position(d), f = track.forward(d);
        const glm::vec3 side = glm::normalize(glm::cross(f, glm::vec3(0.0f, 1.0f, 0.0f)));
        const glm::vec3 q = p + side * 4.0f;  // on the road, off the centre line
        const float found = nearestTrackDistance(track, q.x, q.z);
        const float error = std::min(std::abs(found - d), track.length() - std::abs(found - d));
        EXPECT_LT(error, 0.3f) << "at " << d;
    }
}

TEST(TrackGround, OnTheRoadItsSurfaceElsewhereTheGround) {
    const Track track(1);
    const Ground ground(track);
    for (float d = 0.0f; d < track.length(); d += 37.0f) {
        const glm::vec3 p = track.position(d), f = track.forward(d);
        const glm::vec3 side = glm::normalize(glm::cross(f, glm::vec3(0.0f, 1.0f, 0.0f)));
        for (float across : {-5.5f, 0.0f, 3.0f}) {
            const glm::vec3 q = p + side * across;
            const float h = groundHeight(track, ground, q.x, q.z);
            EXPECT_GE(h, ground.height(q.x, q.z)) << d;
            EXPECT_NEAR(h, p.y, 0.02f) << d << " " << across;  // the road, level across
        }
        const glm::vec3 field = p + side * 30.0f;
        EXPECT_EQ(groundHeight(track, ground, field.x, field.z), ground.height(field.x, field.z));
    }
}

}  // namespace
}  // namespace racer
