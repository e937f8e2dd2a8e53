// SPDX-License-Identifier: MIT
#include "engine/scene/bounds.hpp"

#include <algorithm>

namespace engine::scene {

Aabb Aabb::transformed(const glm::mat4& m) const {
    Aabb out;
    if (empty()) return out;
    for (int i = 0; i < 8; ++i) {
        const glm::vec3 p((i & 1) ? max.x : min.x, (i & 2) ? max.y : min.y, (i & 4) ? max.z : min.z);
        out.add(glm::vec3(m * glm::vec4(p, 1.0f)));
    }
    return out;
}

bool intersectsViewVolume(const Aabb& box, const glm::mat4& viewProj) {
    if (box.empty()) return false;
    glm::vec4 c[8];
    for (int i = 0; i < 8; ++i)
        c[i] = viewProj * glm::vec4((i & 1) ? box.max.x : box.min.x, (i & 2) ? box.max.y : box.min.y,
                                    (i & 4) ? box.max.z : box.min.z, 1.0f);
    auto all = [&](auto outside) { return std::all_of(c, c + 8, outside); };
    return !(all([](const glm::vec4& v) { return v.x > v.w; }) || all([](const glm::vec4& v) { return v.x < -v.w; }) ||
             all([](const glm::vec4& v) { return v.y > v.w; }) || all([](const glm::vec4& v) { return v.y < -v.w; }) ||
             all([](const glm::vec4& v) { return v.z < 0.0f; }) || all([](const glm::vec4& v) { return v.z > v.w; }));
}

}  // namespace engine::scene
