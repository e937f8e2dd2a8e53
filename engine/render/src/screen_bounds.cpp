// SPDX-License-Identifier: MIT
#include "engine/render/screen_bounds.hpp"

#include <algorithm>
#include <cmath>

namespace engine::render {

std::optional<Rect> screenBounds(const BoundingBox& b, const glm::mat4& viewProj, int width, int height) {
    glm::vec4 corners[8];
    for (int i = 0; i < 8; ++i) {
        const glm::vec3 p((i & 1) ? b.max.x : b.min.x, (i & 2) ? b.max.y : b.min.y, (i & 4) ? b.max.z : b.min.z);
        corners[i] = viewProj * glm::vec4(p, 1.0f);
    }
    // Outside when every corner is beyond the same clip plane (x, y in [-w, w], z in [0, w]).
    auto allOutside = [&](auto outside) { return std::all_of(corners, corners + 8, outside); };
    if (allOutside([](const glm::vec4& c) { return c.x > c.w; }) ||
        allOutside([](const glm::vec4& c) { return c.x < -c.w; }) ||
        allOutside([](const glm::vec4& c) { return c.y > c.w; }) ||
        allOutside([](const glm::vec4& c) { return c.y < -c.w; }) ||
        allOutside([](const glm::vec4& c) { return c.z < 0.0f; }) ||
        allOutside([](const glm::vec4& c) { return c.z > c.w; }))
        return std::nullopt;

    const Rect full{0, 0, width, height};
    float minX = INFINITY, minY = INFINITY, maxX = -INFINITY, maxY = -INFINITY;
    for (const glm::vec4& c : corners) {
        // A corner at or behind the camera plane projects to infinity: take the whole screen.
        if (!(c.w > 1e-6f) || !std::isfinite(c.x) || !std::isfinite(c.y)) return full;
        const float x = (c.x / c.w * 0.5f + 0.5f) * width;
        const float y = (0.5f - c.y / c.w * 0.5f) * height;
        minX = std::min(minX, x), maxX = std::max(maxX, x);
        minY = std::min(minY, y), maxY = std::max(maxY, y);
    }
    // One pixel of margin covers the rasterizer's sub-pixel snapping.
    const int x0 = std::clamp(static_cast<int>(std::floor(std::max(minX, -1.0f))) - 1, 0, width);
    const int y0 = std::clamp(static_cast<int>(std::floor(std::max(minY, -1.0f))) - 1, 0, height);
    const int x1 = std::clamp(static_cast<int>(std::ceil(std::min(maxX, width + 1.0f))) + 1, 0, width);
    const int y1 = std::clamp(static_cast<int>(std::ceil(std::min(maxY, height + 1.0f))) + 1, 0, height);
    if (x1 <= x0 || y1 <= y0) return std::nullopt;
    return Rect{x0, y0, x1 - x0, y1 - y0};
}

Rect unite(const Rect& a, const Rect& b) {
    if (a.empty()) return b;
    if (b.empty()) return a;
    const int x0 = std::min(a.x, b.x), y0 = std::min(a.y, b.y);
    const int x1 = std::max(a.x + a.width, b.x + b.width), y1 = std::max(a.y + a.height, b.y + b.height);
    return {x0, y0, x1 - x0, y1 - y0};
}

}  // namespace engine::render
