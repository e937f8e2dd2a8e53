// SPDX-License-Identifier: MIT
#pragma once
// What SSAM draws: the engine's batches of alpha-masked foliage (instanced meshes), as the
// engine already has them. SSAM draws each batch twice, once per pass, with its own programs.
#include <span>

#include <glm/glm.hpp>

#include "engine/render/masked_batch.hpp"
#include "engine/render/program.hpp"

namespace ssam {

struct FoliageView {
    glm::mat4 viewProj{1.0f};
    engine::render::DirectionalLight light;
    std::span<const engine::render::MaskedBatch> batches;
};

}  // namespace ssam
