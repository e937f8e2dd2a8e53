// SPDX-License-Identifier: MIT
#pragma once
// What SSAM draws: batches of alpha-tested foliage (instanced meshes) as the engine
// already has them. SSAM draws each batch twice, once per pass, with its own programs.
#include <cstdint>
#include <span>

#include <glm/glm.hpp>

#include "engine/render/handles.hpp"
#include "engine/render/pass.hpp"
#include "engine/render/program.hpp"
#include "engine/render/texture.hpp"

namespace ssam {

struct Bounds {
    glm::vec3 min{0.0f};
    glm::vec3 max{0.0f};
};

struct FoliageBatch {
    engine::render::BufferHandle vertices;
    engine::render::BufferHandle indices;  // null: non-indexed
    std::uint32_t first = 0;
    std::uint32_t count = 0;
    engine::render::BufferHandle instances;  // null: one instance, identity transform
    std::uint32_t instanceCount = 1;
    engine::render::TextureBinding baseColor;
    glm::vec4 baseColorFactor{1.0f};
    Bounds worldBounds;  // of all instances: decides visibility and the composite region
    bool unlit = false;  // KHR_materials_unlit: the colour pass ignores the view's light
};

// The draw of one batch with a pipeline and its parameters (SSAM's passes and the other
// foliage techniques draw batches the same way).
engine::render::DrawDesc foliageDraw(const FoliageBatch& batch, engine::render::PipelineHandle pipeline,
                                     engine::render::DrawParams params);

struct FoliageView {
    glm::mat4 viewProj{1.0f};
    engine::render::DirectionalLight light;
    std::span<const FoliageBatch> batches;
};

}  // namespace ssam
