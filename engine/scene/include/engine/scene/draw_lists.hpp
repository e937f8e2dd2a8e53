// SPDX-License-Identifier: MIT
#pragma once
// Extraction, the frame's second step (after the systems, before the frame graph): visible
// entities become draw batches — one per mesh part, with every visible instance of it — split
// by surface class.
#include <vector>

#include "engine/core/ecs/registry.hpp"
#include "engine/render/vertex.hpp"
#include "engine/scene/levels_of_detail.hpp"
#include "engine/scene/mesh_library.hpp"

namespace engine::scene {

struct DrawBatch {
    std::uint32_t part = 0;
    // The entity's own deformed copy of the part (VertexOverride, modules/wind); null: the
    // part's shared mesh. A batch with its own vertices holds that one entity's instance.
    render::BufferHandle vertices;
    std::vector<render::Instance> instances;
    Aabb worldBounds;
    float viewDistance = 0.0f;  // of the bounds' centre, for sorting Blend batches
    // The override's motion copy of `vertices` (VertexOverride::motionBuffers); null: none.
    render::BufferHandle motionVertices;
    // The level of detail the part belongs to (0: the full model, or no LevelsOfDetail), and
    // whether the batch holds instances inside a crossfade band (each one's weight in its tint
    // alpha). Crossfading instances are batched apart from steady ones, so that techniques
    // which cannot fade by alpha (alpha testing: a dither instead) change only those draws.
    int level = 0;
    bool crossfading = false;
};

struct DrawLists {
    std::vector<DrawBatch> opaque;
    std::vector<DrawBatch> mask;   // alpha-tested foliage
    std::vector<DrawBatch> blend;  // back to front
    // Instances with LevelsOfDetail drawn (some part in view) at each level (a crossfading
    // instance at both of its levels).
    std::array<std::uint32_t, kMaxLodLevels> instancesAtLevel{};
};

// The vertex buffer a batch draws: its own override, else the part's shared mesh.
inline render::BufferHandle vertexBufferOf(const DrawBatch& batch, const MeshPart& part) {
    return batch.vertices ? batch.vertices : part.vertices;
}

// Every Transform + Renderable entity whose part bounds touch the view volume. Batches
// follow part order (stable across frames); Blend batches one per instance, sorted far to near.
// A part overridden by the entity's VertexOverride gets a batch of its own with that buffer
// and the override's bounds, after the shared batch of the same part. An entity with
// LevelsOfDetail draws the model of its chosen level (levels_of_detail.hpp), or inside a
// crossfade band both levels, each instance's tint alpha its level's weight (else 1), in
// batches of their own after the steady batch of the same part; its VertexOverride belongs to
// level 0's parts and is used only there.
DrawLists extractDrawLists(ecs::Registry& registry, const MeshLibrary& library, const glm::mat4& viewProj,
                           const glm::vec3& cameraPosition);

}  // namespace engine::scene
