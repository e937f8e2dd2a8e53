// SPDX-License-Identifier: MIT
#pragma once
// Motion vectors of rigidly moving entities (the car): an entity marked MovesRigidly gets, while
// the frame reads motion vectors, a motion copy of each of its parts, the same vertices with each
// normal the vertex's previous minus current position in model space, handed to extraction
// through a VertexOverride whose buffers are the shared meshes (so the entity draws as before)
// and whose motionBuffers are the copies (render::MaskedBatch::motionVertices, the same slot the
// wind's bent plants fill).
//
// For a vertex p of an instance whose model matrix went from P (the last update) to M, the
// world motion is P p - M p; the motion pass turns a normal into world space by mat3(M), so the
// copy holds M^-1 P p - p, for which mat3(M) (M^-1 P p - p) = P p - M p exactly (the rigid
// case of [Karis 2014]'s velocity from the previous frame's transform). An entity seen for
// the first time has no motion. The copies' buffers are made once per entity and part and
// reused every frame (steady frames create nothing).
#include <map>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "engine/core/ecs/registry.hpp"
#include "engine/render/owned.hpp"
#include "engine/scene/mesh_library.hpp"

namespace engine::scene {

// Marks an entity whose Transform changes from frame to frame as a whole (the car).
struct MovesRigidly {};

class RigidMotion {
public:
    explicit RigidMotion(const MeshLibrary& library) : library_(library) {}
    RigidMotion(const RigidMotion&) = delete;
    RigidMotion& operator=(const RigidMotion&) = delete;

    // Once a frame, after the entities moved and before extraction. `motionVectors`: the frame
    // reads them (SimulationFrame::motionVectors); false removes the overrides it gave, and
    // computes nothing. An entity that already has another VertexOverride is left alone.
    void update(ecs::Registry& registry, bool motionVectors);
    // Parts given a motion copy by the last update.
    std::size_t motionCopies() const { return motionCopies_; }
    // `e`'s motion copy of its part slot `i` (index into partsOf(model)); empty when it has
    // none. For tests.
    std::span<const render::Vertex> motion(ecs::Entity e, std::size_t i) const;

private:
    struct Moving {
        glm::mat4 previous{1.0f};
        std::vector<render::Owned<render::BufferHandle>> buffers;  // per part slot (null: a Blend part)
        std::vector<std::vector<render::Vertex>> copies;           // what they hold
    };
    void forget(ecs::Registry& registry, ecs::Entity e);

    const MeshLibrary& library_;
    std::map<ecs::Entity, Moving> moving_;  // ordered: deterministic walks
    std::vector<ecs::Entity> marked_;       // update()'s scratch list, kept for its capacity
    std::size_t motionCopies_ = 0;
};

}  // namespace engine::scene
