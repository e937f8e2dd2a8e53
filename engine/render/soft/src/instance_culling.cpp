// SPDX-License-Identifier: MIT
#include "instance_culling.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace engine::render::soft {

PositionBounds positionBounds(std::span<const Vertex> vertices) {
    PositionBounds b;
    if (vertices.empty()) return b;
    b.min = b.max = glm::dvec3(vertices[0].position);
    for (const Vertex& v : vertices) {
        const glm::vec3& p = v.position;
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) return {};
        b.min = glm::min(b.min, glm::dvec3(p));
        b.max = glm::max(b.max, glm::dvec3(p));
    }
    b.usable = true;
    return b;
}

bool instanceOutsideOnePlane(const glm::mat4& mvp, const PositionBounds& bounds, const Viewport& vp) {
    if (!bounds.usable) return false;
    // Row r of the matrix (glm is column-major): clip[r] = sum_j mvp[j][r] * (p, 1)[j].
    auto row = [&](int r) { return glm::dvec4(mvp[0][r], mvp[1][r], mvp[2][r], mvp[3][r]); };
    const glm::dvec4 x = row(0), y = row(1), z = row(2), w = row(3);
    const glm::dvec3 extent = glm::max(glm::abs(bounds.min), glm::abs(bounds.max));
    // The largest |clip coordinate| any point of the box can reach, summed over x, y, z, w:
    // it bounds both the float transform's rounding (a few 1e-7 of it) and the magnitude
    // outsideOnePlane scales its margin by.
    double magnitude = 0.0;
    for (const glm::dvec4& r : {x, y, z, w}) {
        if (!std::isfinite(r.x) || !std::isfinite(r.y) || !std::isfinite(r.z) || !std::isfinite(r.w)) return false;
        magnitude += std::fabs(r.x) * extent.x + std::fabs(r.y) * extent.y + std::fabs(r.z) * extent.z + std::fabs(r.w);
    }
    const double margin = 2.0 * kFrustumRejectMargin * magnitude;
    // The least value of the plane's distance c . (p, 1) over the box (exact for a linear function).
    auto least = [&](const glm::dvec4& c) {
        return std::min(c.x * bounds.min.x, c.x * bounds.max.x) + std::min(c.y * bounds.min.y, c.y * bounds.max.y) +
               std::min(c.z * bounds.min.z, c.z * bounds.max.z) + c.w;
    };
    const double kx = 1.0 + 2.0 / vp.width, ky = 1.0 + 2.0 / vp.height;
    const std::array<glm::dvec4, 7> planes = {x - kx * w, -x - kx * w, y - ky * w, -y - ky * w, -z, z - w, -w};
    return std::any_of(planes.begin(), planes.end(), [&](const glm::dvec4& c) { return least(c) > margin; });
}

}  // namespace engine::render::soft
