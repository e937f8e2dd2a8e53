// SPDX-License-Identifier: MIT
// engine/scene bounds.hpp: Aabb::transformed and intersectsViewVolume take each of the box's
// corners through the matrix once per frame and plant part; they share the corners' products and
// partial sums, and must give the bits of glm's m * vec4(corner, 1) corner by corner (the boxes
// feed culling, batch bounds and view distances, so every picture depends on them).
#include <algorithm>
#include <cstring>

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "lcg.hpp"  // tests/support
#include "engine/render/projection.hpp"
#include "engine/scene/bounds.hpp"

namespace {

using engine::scene::Aabb;
using ssam::testing::Lcg;

bool sameBits(const glm::vec3& a, const glm::vec3& b) { return std::memcmp(&a, &b, sizeof a) == 0; }

glm::vec4 corner(const Aabb& box, int i) {
    return {(i & 1) ? box.max.x : box.min.x, (i & 2) ? box.max.y : box.min.y, (i & 4) ? box.max.z : box.min.z, 1.0f};
}

// The definitions, corner by corner with glm.
Aabb transformedByCorners(const Aabb& box, const glm::mat4& m) {
    Aabb out;
    if (box.empty()) return out;
    for (int i = 0; i < 8; ++i) out.add(glm::vec3(m * corner(box, i)));
    return out;
}
bool insideByCorners(const Aabb& box, const glm::mat4& m) {
    if (box.empty()) return false;
    glm::vec4 c[8];
    for (int i = 0; i < 8; ++i) c[i] = m * corner(box, i);
    auto all = [&](auto outside) { return std::all_of(c, c + 8, outside); };
    return !(all([](const glm::vec4& v) { return v.x > v.w; }) || all([](const glm::vec4& v) { return v.x < -v.w; }) ||
             all([](const glm::vec4& v) { return v.y > v.w; }) || all([](const glm::vec4& v) { return v.y < -v.w; }) ||
             all([](const glm::vec4& v) { return v.z < 0.0f; }) || all([](const glm::vec4& v) { return v.z > v.w; }));
}

TEST(SceneBounds, CornersGiveGlmsBits) {
    Lcg rng{31};
    int inside = 0, outside = 0;
    for (int n = 0; n < 20'000; ++n) {
        // A model matrix (rotation, scale, translation) and a camera, as the scene has, and now
        // and then a random matrix with every entry free.
        glm::mat4 m(1.0f);
        if (n % 5 == 0) {
            for (int c = 0; c < 4; ++c)
                for (int r = 0; r < 4; ++r) m[c][r] = rng.range(-50.0f, 50.0f);
        } else {
            m = glm::translate(m, glm::vec3(rng.range(-500, 500), rng.range(-5, 30), rng.range(-500, 500)));
            m = glm::rotate(m, rng.range(-3.2f, 3.2f),
                            glm::normalize(glm::vec3(rng.range(-1, 1), 1, rng.range(-1, 1))));
            m = glm::scale(m, glm::vec3(rng.range(0.2f, 3.0f)));
        }
        Aabb box;
        box.add(glm::vec3(rng.range(-10, 10), rng.range(-10, 10), rng.range(-10, 10)));
        box.add(glm::vec3(rng.range(-10, 10), rng.range(-10, 10), rng.range(-10, 10)));
        const Aabb want = transformedByCorners(box, m), got = box.transformed(m);
        ASSERT_TRUE(sameBits(got.min, want.min) && sameBits(got.max, want.max)) << "case " << n;

        const glm::vec3 eye(rng.range(-400, 400), rng.range(1, 20), rng.range(-400, 400));
        const glm::mat4 viewProj =
            engine::render::perspectiveReverseZ(1.0f, 1.7f, 0.1f, 2000.0f) *
            glm::lookAt(eye, eye + glm::vec3(rng.range(-1, 1), 0.0f, rng.range(-1, 1)), glm::vec3(0, 1, 0));
        const bool expected = insideByCorners(got, viewProj);
        ASSERT_EQ(engine::scene::intersectsViewVolume(got, viewProj), expected) << "case " << n;
        (expected ? inside : outside) += 1;
    }
    // Both answers were met, so the comparison saw each.
    EXPECT_GT(inside, 1000);
    EXPECT_GT(outside, 1000);
}

TEST(SceneBounds, EmptyAndNonFiniteBoxes) {
    const glm::mat4 m = glm::translate(glm::mat4(1.0f), glm::vec3(1, 2, 3));
    EXPECT_TRUE(Aabb{}.transformed(m).empty());
    EXPECT_FALSE(engine::scene::intersectsViewVolume(Aabb{}, m));
    Aabb nan;
    nan.min = glm::vec3(0.0f), nan.max = glm::vec3(1.0f, std::nanf(""), 1.0f);
    EXPECT_TRUE(nan.empty());
    EXPECT_TRUE(nan.transformed(m).empty());
}

}  // namespace
