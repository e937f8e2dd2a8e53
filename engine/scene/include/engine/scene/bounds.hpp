// SPDX-License-Identifier: MIT
#pragma once
// Axis-aligned boxes and the view-volume test extraction uses to skip what can't be seen.
#include <limits>

#include <glm/glm.hpp>

namespace engine::scene {

struct Aabb {
    glm::vec3 min{std::numeric_limits<float>::infinity()};
    glm::vec3 max{-std::numeric_limits<float>::infinity()};

    bool empty() const { return !(min.x <= max.x && min.y <= max.y && min.z <= max.z); }
    void add(const glm::vec3& p) {
        min = glm::min(min, p);
        max = glm::max(max, p);
    }
    void add(const Aabb& b) {
        if (!b.empty()) add(b.min), add(b.max);
    }
    Aabb transformed(const glm::mat4& m) const;  // box of the 8 transformed corners
};

// False only when the box is certainly outside the clip volume (x, y in [-w, w], z in [0, w]).
bool intersectsViewVolume(const Aabb& box, const glm::mat4& viewProj);

}  // namespace engine::scene
