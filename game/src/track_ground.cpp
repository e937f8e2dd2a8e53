// SPDX-License-Identifier: MIT
#include "track_ground.hpp"

#include <algorithm>
#include <cmath>

namespace racer {

namespace {

float horizontalDistance2(const glm::vec3& p, float x, float z) {
    const float dx = p.x - x, dz = p.z - z;
    return dx * dx + dz * dz;
}

// The best of `count` samples `step` apart from `first` (the first on ties: deterministic).
float bestSample(const Track& track, float x, float z, float first, float step, int count) {
    float best = first, bestD2 = horizontalDistance2(track.position(first), x, z);
    for (int i = 1; i < count; ++i) {
        const float d = first + step * float(i);
        const float d2 = horizontalDistance2(track.position(d), x, z);
        if (d2 < bestD2) best = d, bestD2 = d2;
    }
    return best;
}

}  // namespace

float nearestTrackDistance(const Track& track, float x, float z) {
    constexpr float kCoarse = 2.0f, kFine = 0.1f;
    const int coarse = std::max(1, int(std::ceil(track.length() / kCoarse)));
    const float near = bestSample(track, x, z, 0.0f, kCoarse, coarse);
    const float refined = bestSample(track, x, z, near - kCoarse, kFine, int(2.0f * kCoarse / kFine) + 1);
    const float d = std::fmod(refined, track.length());
    return d < 0.0f ? d + track.length() : d;
}

float groundHeight(const Track& track, const Ground& ground, float x, float z) {
    const float below = ground.height(x, z);
    const float d = nearestTrackDistance(track, x, z);
    const glm::vec3 p = track.position(d), f = track.forward(d);
    const glm::vec3 side = glm::normalize(glm::cross(f, glm::vec3(0.0f, 1.0f, 0.0f)));
    const float across = glm::dot(glm::vec3(x, 0.0f, z) - glm::vec3(p.x, 0.0f, p.z), side);
    if (std::abs(across) > 0.5f * track.width()) return below;
    return std::max(below, p.y);  // the road mesh is level across at the centre line's height
}

}  // namespace racer
