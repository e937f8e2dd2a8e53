// SPDX-License-Identifier: MIT
#pragma once
// Perspective projections for the engine's clip convention (depth = z/w in [0, 1]).
// Reverse-Z maps the near plane to 1 and the far plane to 0: float depth then has its
// densest values where distances are largest, which keeps the 0.1 m .. 30 km range of
// Pure's vistas ([Hathaway 2010] §3.1) resolvable; use it with CompareFunc::Greater and clear 0.
#include <cmath>

#include <glm/glm.hpp>

namespace engine::render {

// Conventional: depth 0 at `near`, 1 at `far` (glm::perspectiveRH_ZO).
inline glm::mat4 perspectiveZeroToOne(float fovY, float aspect, float near, float far) {
    // tan in double, then rounded: GCC folds tanf of a constant angle to the correctly rounded
    // float at -O2, while a Debug build calls glibc's tanf, one ulp away for 30 degrees; the
    // double result rounds to that same float either way, so images do not depend on the build.
    const float f = 1.0f / static_cast<float>(std::tan(0.5 * static_cast<double>(fovY)));
    glm::mat4 m(0.0f);
    m[0][0] = f / aspect;
    m[1][1] = f;
    m[2][2] = -far / (far - near);
    m[2][3] = -1.0f;
    m[3][2] = -far * near / (far - near);
    return m;
}

// Reverse-Z: depth 1 at `near`, 0 at `far`; depth = near*(far - d) / (d*(far - near)) at distance d.
inline glm::mat4 perspectiveReverseZ(float fovY, float aspect, float near, float far) {
    // tan in double, then rounded: GCC folds tanf of a constant angle to the correctly rounded
    // float at -O2, while a Debug build calls glibc's tanf, one ulp away for 30 degrees; the
    // double result rounds to that same float either way, so images do not depend on the build.
    const float f = 1.0f / static_cast<float>(std::tan(0.5 * static_cast<double>(fovY)));
    glm::mat4 m(0.0f);
    m[0][0] = f / aspect;
    m[1][1] = f;
    m[2][2] = near / (far - near);
    m[2][3] = -1.0f;
    m[3][2] = far * near / (far - near);
    return m;
}

}  // namespace engine::render
