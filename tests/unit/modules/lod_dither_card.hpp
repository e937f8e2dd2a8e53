// SPDX-License-Identifier: MIT
#pragma once
// DitheredMaskedLit (transparency/lod_dither.hpp) drawn straight into a float target, for its
// soft and GPU tests: a screen-filling untextured card whose vertex alpha is the crossfade
// weight, so the output alpha is 1 (the weight divided out) where the level keeps the pixel
// and 0 where the other level does.
#include <vector>

#include "engine/render/backend.hpp"
#include "engine/render/program.hpp"
#include "program_card.hpp"
#include "run_technique.hpp"  // cardVertices
#include "transparency/lod_dither.hpp"

namespace transparency::testing {

inline constexpr int kDitherCardPixels = 16;

inline engine::render::Readback drawDitheredCard(engine::render::Backend& backend, float weight, LodDither dither) {
    const glm::vec3 corners[4] = {{-1, -1, 0.5f}, {1, -1, 0.5f}, {1, 1, 0.5f}, {-1, 1, 0.5f}};
    const std::vector<engine::render::Vertex> vertices =
        test_support::cardVertices(corners, 1.0f, glm::vec4(1.0f, 1.0f, 1.0f, weight));
    DitheredSurfaceParams params;
    params.light = engine::render::unlitLight();
    params.lodDither = dither;
    return test_support::drawProgramCard(backend, ditheredMaskedLitProgram(), params, vertices, kDitherCardPixels);
}

}  // namespace transparency::testing
