// SPDX-License-Identifier: MIT
#include "verge.hpp"

#include "ground.hpp"
#include "track.hpp"

namespace racer {

std::vector<engine::scene::GroundSpot> vergeAlong(const Track& track, std::uint32_t seed) {
    const Ground ground(track);
    Random random(seed * 31u + 7u);
    std::vector<engine::scene::GroundSpot> spots;
    for (float d = 0.0f; d < track.length(); d += 0.8f) {
        const glm::vec3 p = track.position(d), f = track.forward(d);
        const glm::vec3 side = glm::normalize(glm::cross(f, glm::vec3(0.0f, 1.0f, 0.0f)));
        for (int row = 0; row < 6; ++row) {
            const float offset =
                track.width() * 0.5f + Track::kShoulderWidth + 0.3f + float(row) * 1.6f + random.uniform(0.0f, 1.2f);
            glm::vec3 q = p + side * (row % 2 ? offset : -offset) + f * random.uniform(-0.4f, 0.4f);
            q.y = ground.height(q.x, q.z);
            spots.push_back({q, random.uniform(0.0f, 6.2832f), random.uniform(0.7f, 1.3f)});
        }
    }
    return spots;
}

}  // namespace racer
