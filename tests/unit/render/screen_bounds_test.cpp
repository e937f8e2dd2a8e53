// SPDX-License-Identifier: MIT
#include <gtest/gtest.h>

#include "engine/render/screen_bounds.hpp"

namespace {

TEST(ScreenRegion, ProjectsBoundsToPixelsWithMargin) {
    const auto r = engine::render::screenBounds({{-0.5f, -0.5f, 0.5f}, {0.5f, 0.5f, 0.5f}}, glm::mat4(1.0f), 100, 100);
    ASSERT_TRUE(r);
    EXPECT_EQ(r->x, 24);
    EXPECT_EQ(r->y, 24);
    EXPECT_EQ(r->width, 52);
    EXPECT_EQ(r->height, 52);
}

TEST(ScreenRegion, CullsBoundsOutsideTheViewVolume) {
    EXPECT_FALSE(engine::render::screenBounds({{2, 2, 0.5f}, {3, 3, 0.5f}}, glm::mat4(1.0f), 64, 64));
    EXPECT_FALSE(
        engine::render::screenBounds({{-1, -1, -2}, {1, 1, -1}}, glm::mat4(1.0f), 64, 64));  // z < 0: beyond near/far
}

TEST(ScreenRegion, CrossingTheCameraPlaneTakesTheWholeScreen) {
    glm::mat4 m(1.0f);
    m[3][3] = 0.0f;  // w = z: a corner with z <= 0 sits on or behind the camera plane
    m[2][3] = 1.0f;
    const auto r = engine::render::screenBounds({{-1, -1, -1}, {1, 1, 1}}, m, 64, 48);
    ASSERT_TRUE(r);
    EXPECT_EQ(r->width, 64);
    EXPECT_EQ(r->height, 48);
}

TEST(ScreenRegion, UniteIgnoresEmpty) {
    const engine::render::Rect a{1, 2, 3, 4}, empty{};
    EXPECT_EQ(engine::render::unite(a, empty).width, 3);
    const auto u = engine::render::unite(a, {10, 10, 2, 2});
    EXPECT_EQ(u.x, 1);
    EXPECT_EQ(u.width, 11);
    EXPECT_EQ(u.height, 10);
}

}  // namespace
