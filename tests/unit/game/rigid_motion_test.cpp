// SPDX-License-Identifier: MIT
// engine/scene rigid_motion.hpp, the car's motion vectors: an entity marked MovesRigidly gets a
// motion copy of each part, whose normal turned into world space by this frame's model matrix
// (as the motion pass does) is the vertex's previous minus current world position; none without
// the frame's request; extraction hands the copy to the entity's opaque batch.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "engine/render/projection.hpp"
#include "engine/render/soft/soft_backend.hpp"
#include "engine/scene/components.hpp"
#include "engine/scene/draw_lists.hpp"
#include "engine/scene/rigid_motion.hpp"

namespace {

using namespace engine;

struct BoxScene {
    std::unique_ptr<render::Device> backend = render::soft::createSoftBackend({1, 64, false});
    scene::MeshLibrary library{*backend};
    ecs::Registry registry;
    scene::RigidMotion motion{library};
    ecs::Entity box = registry.create();
    glm::mat4 viewProj = render::perspectiveReverseZ(1.0f, 1.5f, 0.1f, 1000.0f) *
                         glm::lookAt(glm::vec3(0, 2, -10), glm::vec3(0, 0, 0), glm::vec3(0, 1, 0));

    BoxScene() {
        std::vector<render::Vertex> v(4);
        const glm::vec3 corners[4] = {{-1, 0, 0}, {1, 0, 0}, {1, 2, 0.5f}, {-1, 2, 0.5f}};
        for (int i = 0; i < 4; ++i) v[std::size_t(i)].position = corners[i];
        const scene::ModelId model = library.add("box", v, {0, 1, 2, 0, 2, 3}, scene::PartMaterial{});
        registry.add<scene::Transform>(box);
        registry.add<scene::Renderable>(box, scene::Renderable{model});
        registry.add<scene::MovesRigidly>(box);
    }
    std::span<const render::Vertex> copy() {
        EXPECT_TRUE(registry.get<scene::VertexOverride>(box).motionBuffers.at(0));
        return motion.motion(box, 0);
    }
};

TEST(RigidMotion, TheMotionCopyTurnedIntoWorldSpaceIsTheVertexsMotion) {
    BoxScene s;
    s.motion.update(s.registry, false);
    EXPECT_FALSE(s.registry.has<scene::VertexOverride>(s.box)) << "no motion copy without the frame's request";
    EXPECT_EQ(s.motion.motionCopies(), 0u);

    s.motion.update(s.registry, true);  // first seen: no motion yet
    ASSERT_EQ(s.motion.motionCopies(), 1u);
    for (const render::Vertex& v : s.copy()) EXPECT_EQ(v.normal, glm::vec3(0.0f));

    const glm::mat4 previous = s.registry.get<scene::Transform>(s.box).matrix();
    scene::Transform& t = s.registry.get<scene::Transform>(s.box);
    t.position = {0.7f, 0.1f, 1.3f};
    t.rotation = glm::angleAxis(0.3f, glm::normalize(glm::vec3(0.2f, 1.0f, 0.1f)));
    const glm::mat4 model = t.matrix();
    s.motion.update(s.registry, true);
    const auto rest = s.library.vertices(s.library.partsOf(s.registry.get<scene::Renderable>(s.box).model)[0]);
    const auto copy = s.copy();
    ASSERT_EQ(copy.size(), rest.size());
    for (std::size_t i = 0; i < copy.size(); ++i) {
        EXPECT_EQ(copy[i].position, rest[i].position) << i;
        const glm::vec3 world = glm::mat3(model) * copy[i].normal;
        const glm::vec3 expected = glm::vec3(previous * glm::vec4(rest[i].position, 1.0f)) -
                                   glm::vec3(model * glm::vec4(rest[i].position, 1.0f));
        EXPECT_LT(glm::length(world - expected), 1e-5f) << i;
        EXPECT_GT(glm::length(expected), 0.1f) << i;
    }

    const scene::DrawLists lists = scene::extractDrawLists(s.registry, s.library, s.viewProj, glm::vec3(0, 2, -10));
    ASSERT_EQ(lists.opaque.size(), 1u);
    EXPECT_EQ(lists.opaque[0].motionVertices, s.registry.get<scene::VertexOverride>(s.box).motionBuffers[0]);
    EXPECT_EQ(scene::vertexBufferOf(lists.opaque[0], s.library.part(lists.opaque[0].part)),
              s.library.part(lists.opaque[0].part).vertices)
        << "the entity draws its shared mesh as before";

    s.motion.update(s.registry, false);
    EXPECT_FALSE(s.registry.has<scene::VertexOverride>(s.box)) << "the request gone, the override goes";
}

}  // namespace
