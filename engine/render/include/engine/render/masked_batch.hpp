// SPDX-License-Identifier: MIT
#pragma once
// A batch of alpha-masked surfaces (instanced meshes whose base colour alpha cuts them out:
// leaves, fences, hair cards) as an engine keeps them for drawing. Each technique that
// resolves alpha masks (alpha testing, alpha-to-coverage, sorted blending, screen-space
// masking, an exact reference) draws the same batches with its own pipelines and parameters.
#include <cstdint>

#include <glm/glm.hpp>

#include "engine/render/handles.hpp"
#include "engine/render/pass.hpp"
#include "engine/render/program.hpp"
#include "engine/render/texture.hpp"

namespace engine::render {

// An axis-aligned box in world (or model) space.
struct BoundingBox {
    glm::vec3 min{0.0f};
    glm::vec3 max{0.0f};
};

struct MaskedBatch {
    BufferHandle vertices;
    BufferHandle indices;  // null: non-indexed
    std::uint32_t first = 0;
    std::uint32_t count = 0;
    BufferHandle instances;  // null: one instance, identity transform
    std::uint32_t instanceCount = 1;
    TextureBinding baseColor;
    glm::vec4 baseColorFactor{1.0f};
    BoundingBox worldBounds;  // of all instances: decides visibility and the screen region touched
    bool unlit = false;       // KHR_materials_unlit: lit programs ignore the light
    // The same vertices with each normal replaced by the vertex's motion since the previous
    // frame, previous minus current position in model space (the instance matrix turns it into
    // world space as it does normals), for the temporal pass's motion vectors; null: the surface
    // did not move (static, or a first frame), only the camera's motion applies.
    BufferHandle motionVertices;
};

// The draw of one batch with a pipeline and its parameters.
DrawDesc maskedBatchDraw(const MaskedBatch& batch, PipelineHandle pipeline, DrawParams params);

}  // namespace engine::render
