// SPDX-License-Identifier: MIT
#include "engine/scene/bounds.hpp"

#include <algorithm>
#include <array>
#include <cstddef>

namespace engine::scene {

namespace {

// m * vec4(corner, 1) for the box's 8 corners (corner i takes max.x where bit 0 of i is set, max.y
// for bit 1, max.z for bit 2) with the operations glm's mat4 * vec4 does, in its order,
// (m[0] x + m[1] y) + (m[2] z + m[3] w), so the same bits; each product and partial sum the
// corners share is taken once (the scene culls every plant part with this, every frame).
std::array<glm::vec4, 8> transformedCorners(const Aabb& box, const glm::mat4& m) {
    const glm::vec4 x[2] = {m[0] * box.min.x, m[0] * box.max.x};
    const glm::vec4 y[2] = {m[1] * box.min.y, m[1] * box.max.y};
    const glm::vec4 w = m[3] * 1.0f;  // glm multiplies by w = 1 too (a NaN comes out as it would there)
    const glm::vec4 zw[2] = {m[2] * box.min.z + w, m[2] * box.max.z + w};
    const glm::vec4 xy[4] = {x[0] + y[0], x[1] + y[0], x[0] + y[1], x[1] + y[1]};
    std::array<glm::vec4, 8> corners;
    for (int i = 0; i < 8; ++i) corners[std::size_t(i)] = xy[i & 3] + zw[i >> 2];
    return corners;
}

}  // namespace

Aabb Aabb::transformed(const glm::mat4& m) const {
    Aabb out;
    if (empty()) return out;
    for (const glm::vec4& c : transformedCorners(*this, m)) out.add(glm::vec3(c));
    return out;
}

bool intersectsViewVolume(const Aabb& box, const glm::mat4& viewProj) {
    if (box.empty()) return false;
    const std::array<glm::vec4, 8> c = transformedCorners(box, viewProj);
    auto all = [&](auto outside) { return std::all_of(c.begin(), c.end(), outside); };
    return !(all([](const glm::vec4& v) { return v.x > v.w; }) || all([](const glm::vec4& v) { return v.x < -v.w; }) ||
             all([](const glm::vec4& v) { return v.y > v.w; }) || all([](const glm::vec4& v) { return v.y < -v.w; }) ||
             all([](const glm::vec4& v) { return v.z < 0.0f; }) || all([](const glm::vec4& v) { return v.z > v.w; }));
}

}  // namespace engine::scene
