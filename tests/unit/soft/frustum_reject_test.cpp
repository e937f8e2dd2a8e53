// SPDX-License-Identifier: MIT
// The frustum rejects that skip work before triangle setup (outsideOnePlane) and before the
// vertex stage (instanceOutsideOnePlane): where they reject, the exact pipeline would have
// dropped the triangle anyway, so they must never reject a triangle that reaches a pixel.
#include <random>

#include <glm/gtc/matrix_transform.hpp>

#include "instance_culling.hpp"  // engine/render/soft/src
#include "soft_test_util.hpp"

namespace ssam::test::soft {
namespace {

using engine::render::soft::ClipVertex;
using engine::render::soft::instanceOutsideOnePlane;
using engine::render::soft::outsideOnePlane;
using engine::render::soft::positionBounds;
using engine::render::soft::PositionBounds;
using engine::render::soft::Viewport;

ClipVertex at(float x, float y, float z = 0.5f, float w = 1.0f) {
    ClipVertex v{};
    v.position = {x, y, z, w};
    return v;
}

const Viewport kViewport{100, 50, {0, 0, 100, 50}};

TEST(FrustumReject, KeepsTrianglesThatReachTheViewportOrItsEdgePixels) {
    EXPECT_FALSE(outsideOnePlane(at(-0.5f, -0.5f), at(0.5f, -0.5f), at(0.0f, 0.5f), kViewport));
    // Within a pixel beyond the right edge (a pixel is 0.02 NDC wide here): left to the
    // exact set-up, which snaps such a triangle and drops it by its pixel box.
    EXPECT_FALSE(outsideOnePlane(at(1.0f, 0.0f), at(1.01f, 0.0f), at(1.01f, 0.5f), kViewport));
    // One vertex inside is enough to keep it.
    EXPECT_FALSE(outsideOnePlane(at(0.9f, 0.0f), at(3.0f, 0.0f), at(3.0f, 0.5f), kViewport));
    // Crossing the eye plane (w < 0 at two vertices, visible at the third).
    EXPECT_FALSE(outsideOnePlane(at(0.0f, 0.0f, 0.5f, 1.0f), at(0.0f, 0.0f, -0.5f, -1.0f), at(1.0f, 1.0f, -0.5f, -1.0f),
                                 kViewport));
}

TEST(FrustumReject, RejectsTrianglesBeyondOnePlane) {
    EXPECT_TRUE(outsideOnePlane(at(1.1f, 0.0f), at(2.0f, 0.0f), at(2.0f, 0.5f), kViewport));           // right
    EXPECT_TRUE(outsideOnePlane(at(-1.1f, 0.0f), at(-2.0f, 0.0f), at(-2.0f, 0.5f), kViewport));        // left
    EXPECT_TRUE(outsideOnePlane(at(0.0f, 1.1f), at(0.5f, 2.0f), at(-0.5f, 3.0f), kViewport));          // top
    EXPECT_TRUE(outsideOnePlane(at(0.0f, -1.1f), at(0.5f, -2.0f), at(-0.5f, -3.0f), kViewport));       // bottom
    EXPECT_TRUE(outsideOnePlane(at(0, 0, -0.1f), at(1, 0, -0.2f), at(0, 1, -0.3f), kViewport));        // z < 0
    EXPECT_TRUE(outsideOnePlane(at(0, 0, 1.1f), at(1, 0, 1.2f), at(0, 1, 1.3f), kViewport));           // z > w
    EXPECT_TRUE(outsideOnePlane(at(0, 0, 0, -1), at(0.1f, 0, 0, -2), at(0, 0.1f, 0, -3), kViewport));  // behind
}

// The property the instance reject relies on: when it rejects a box under a matrix, every
// triangle of points in that box, transformed in float as the vertex stage does, is rejected
// by outsideOnePlane, so skipping the instance changes neither pixels nor counters.
TEST(FrustumReject, AnInstanceRejectedWholeHasEveryTriangleRejected) {
    std::mt19937 random(7);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    const glm::mat4 projection = glm::perspective(1.0f, 2.0f, 0.1f, 500.0f);
    const glm::mat4 view = glm::lookAt(glm::vec3(0, 2, 0), glm::vec3(0, 2, -10), glm::vec3(0, 1, 0));
    const std::vector<render::Vertex> mesh = [&] {
        std::vector<render::Vertex> v(64);
        for (render::Vertex& p : v) p.position = {unit(random), unit(random) + 1.0f, unit(random)};
        return v;
    }();
    const PositionBounds bounds = positionBounds(mesh);
    ASSERT_TRUE(bounds.usable);
    int rejected = 0, kept = 0;
    for (int i = 0; i < 4000; ++i) {
        // Instances scattered around the camera, many just beyond a side of the view.
        const glm::vec3 place(unit(random) * 60.0f, unit(random) * 10.0f, unit(random) * 60.0f);
        const glm::mat4 model =
            glm::scale(glm::translate(glm::mat4(1.0f), place), glm::vec3(0.5f + unit(random) * 0.4f));
        const glm::mat4 mvp = projection * view * model;
        if (!instanceOutsideOnePlane(mvp, bounds, kViewport)) {
            ++kept;
            continue;
        }
        ++rejected;
        for (std::size_t t = 0; t + 2 < mesh.size(); ++t) {
            ClipVertex cv[3];
            for (int k = 0; k < 3; ++k) cv[k].position = mvp * glm::vec4(mesh[t + std::size_t(k)].position, 1.0f);
            ASSERT_TRUE(outsideOnePlane(cv[0], cv[1], cv[2], kViewport)) << "instance " << i << " triangle " << t;
        }
    }
    EXPECT_GT(rejected, 1000);
    EXPECT_GT(kept, 100);
}

TEST(FrustumReject, MeshesWithNonFinitePositionsAreNeverRejectedWhole) {
    std::vector<render::Vertex> mesh(3);
    mesh[1].position.x = std::numeric_limits<float>::infinity();
    EXPECT_FALSE(positionBounds(mesh).usable);
    EXPECT_FALSE(positionBounds({}).usable);
    const glm::mat4 farRight = glm::translate(glm::mat4(1.0f), glm::vec3(10.0f, 0.0f, 0.0f));
    EXPECT_FALSE(instanceOutsideOnePlane(farRight, positionBounds(mesh), kViewport));
}

// Instances off the target are counted as dropped (every triangle), the others drawn as before.
TEST(FrustumReject, InstancesOffTheTargetAreDroppedAndCounted) {
    auto gfx = createSoftBackend({.threads = 1});
    const render::TextureHandle target = makeTarget(*gfx, 8, 8);
    const render::BufferHandle quad = makeVertices(*gfx, fullQuad());
    std::vector<render::Instance> instances(3);
    instances[1].model = glm::translate(glm::mat4(1.0f), glm::vec3(5.0f, 0.0f, 0.0f));   // off to the right
    instances[2].model = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, -2.5f, 0.0f));  // below
    const render::BufferHandle instanceBuffer = gfx->createBuffer(
        {"instances", render::BufferKind::Instance, instances.size() * sizeof(render::Instance)}, bytesOf(instances));
    render::DrawDesc draw = flatDraw(gfx->createPipeline({}), quad, 6);
    draw.instances = instanceBuffer;
    draw.instanceCount = 3;
    gfx->beginPass(onePass(target));
    gfx->draw(draw);
    gfx->endPass();
    const engine::render::soft::SoftStats s = softDriver(*gfx).stats();
    EXPECT_EQ(s.trianglesIn, 6u);
    EXPECT_EQ(s.trianglesRasterized, 2u);
    EXPECT_EQ(s.trianglesDropped, 4u);
    EXPECT_EQ(s.pixelsShaded, 64u);
}

}  // namespace
}  // namespace ssam::test::soft
