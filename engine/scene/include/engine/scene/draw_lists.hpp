#pragma once
// Extraction (DESIGN.md "Data flow of one frame", step 2): visible entities become draw
// batches — one per mesh part, with every visible instance of it — split by surface class.
#include <vector>

#include "engine/core/ecs/registry.hpp"
#include "engine/render/vertex.hpp"
#include "engine/scene/mesh_library.hpp"

namespace engine::scene {

struct DrawBatch {
    std::uint32_t part = 0;
    std::vector<render::Instance> instances;
    Aabb worldBounds;
    float viewDistance = 0.0f;  // of the bounds' centre, for sorting Blend batches
};

struct DrawLists {
    std::vector<DrawBatch> opaque;
    std::vector<DrawBatch> mask;   // alpha-tested foliage
    std::vector<DrawBatch> blend;  // back to front
};

// Every Transform + Renderable entity whose part bounds touch the view volume. Batches
// follow part order (stable across frames); Blend batches one per instance, sorted far to near.
DrawLists extractDrawLists(ecs::Registry& registry, const MeshLibrary& library, const glm::mat4& viewProj,
                           const glm::vec3& cameraPosition);

}  // namespace engine::scene
