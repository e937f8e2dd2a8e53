// SPDX-License-Identifier: MIT
#pragma once
// The two quads the soft technique tests draw into the 16x16 frame (technique_fixture.hpp), the
// pixels where they are seen alone and together, and the colour check those tests share.
#include <string>

#include <gtest/gtest.h>

#include "technique_fixture.hpp"

namespace transparency::testing {

// A (red, alpha 0.4, nearer) covers the left 5/8, B (green, alpha 0.6, farther) the right 5/8.
inline const Quad kQuadA{-1.0f, -1.0f, 0.25f, 1.0f, 0.3f, {1.0f, 0.0f, 0.0f, 0.4f}};
inline const Quad kQuadB{-0.25f, -1.0f, 1.0f, 1.0f, 0.6f, {0.0f, 1.0f, 0.0f, 0.6f}};
inline constexpr int kOnlyA = 1, kOverlap = 8, kOnlyB = 14;  // pixel columns
inline constexpr int kRow = 5;

inline void expectRgbNear(const glm::vec3& got, const glm::vec3& want, float tolerance, const std::string& where) {
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], want[c], tolerance) << where << " channel " << c;
}

}  // namespace transparency::testing
