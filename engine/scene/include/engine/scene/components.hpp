// SPDX-License-Identifier: MIT
#pragma once
// Components the scene's systems and extraction work on.
#include <vector>

#include "engine/scene/mesh_library.hpp"
#include "engine/scene/transform.hpp"

namespace engine::scene {

// Draws a model at the entity's Transform.
struct Renderable {
    ModelId model = 0;
};

// Pushes foliage away (modules/wind) and marks what the car is.
struct Collider {
    float radius = 1.0f;
};

// Per-entity vertex buffers that replace the shared mesh of some of the entity's parts
// (deformed foliage, modules/wind). Entry i belongs to partsOf(model)[i]; a null buffer keeps
// the shared mesh. `bounds` (model space, same indexing) covers the deformed vertices, so
// extraction culls what is really drawn; an empty box falls back to the part's bounds.
// `motionBuffers` (same indexing, may be empty): the same vertices with each normal the
// vertex's previous minus current position, for motion vectors (render::MaskedBatch::motionVertices).
struct VertexOverride {
    std::vector<render::BufferHandle> buffers;
    std::vector<Aabb> bounds;
    std::vector<render::BufferHandle> motionBuffers;
};

}  // namespace engine::scene
