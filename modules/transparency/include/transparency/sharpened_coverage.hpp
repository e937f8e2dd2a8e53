// SPDX-License-Identifier: MIT
#pragma once
// Sharpened alpha to coverage [Golus 2017] ("Anti-aliased Alpha Test: The Esoteric Alpha To
// Coverage"): plain alpha to coverage turns alpha into a coverage fraction, so a texture's
// soft alpha edge becomes a wide band of partial coverage and the leaf looks blurred and
// thinner at a distance. Golus rescales alpha around the alpha test's reference by its
// screen-space derivative first,
//     alpha' = (alpha - reference) / max(fwidth(alpha), 1e-4) + 0.5,
// so the edge is one pixel wide wherever it lies: anti-aliased like alpha to coverage, as
// sharp as the alpha test (the shape the alpha test draws, alpha' crosses 0.5 exactly where
// alpha crosses the reference).
//
// fwidth is the fine derivative of a 2x2 quad, |a(x|1) - a(x&~1)| + |a(y|1) - a(y&~1)|: GLSL's
// fwidthFine. The soft backend shades pixel by pixel, so its kernel takes the texture's alpha
// at the quad partner's uv, this pixel's uv moved one pixel by the rasterizer's analytic
// derivatives (duv) and sampled with the same derivatives; GL and Vulkan take the partner's
// own interpolated uv and level of detail. The two agree up to the curvature of the
// perspective over one pixel (techniques_gpu_test.cpp states by how much).
#include <algorithm>

#include <glm/glm.hpp>

#include "engine/render/program.hpp"
#include "engine/render/program_desc.hpp"
#include "engine/render/texture.hpp"
#include "transparency/lod_dither.hpp"

namespace transparency {

// The smallest derivative divided by: flat alpha (a derivative of 0) gives full or no coverage.
inline constexpr float kSharpenedCoverageMinWidth = 1e-4f;

// [Golus 2017]: alpha rescaled around `reference` by its screen-space width, in [0, 1].
inline float sharpenedCoverage(float alpha, float width, float reference) {
    const float sharpened = (alpha - reference) / std::max(width, kSharpenedCoverageMinWidth) + 0.5f;
    return std::clamp(sharpened, 0.0f, 1.0f);
}

// SharpenedCoverageLit: the MaskedLit surface (the same colour bits), its alpha sharpened for
// an alpha-to-coverage pipeline.
struct SharpenedCoverageParams {
    glm::mat4 viewProj{1.0f};
    glm::vec4 baseColorFactor{1.0f};
    engine::render::TextureBinding baseColor;
    engine::render::DirectionalLight light;
    float reference = 0.5f;                // the alpha test's reference, in [0, 1]
    LodDither lodDither = LodDither::Off;  // a crossfading batch's level (lod_dither.hpp)
};

engine::render::ProgramDesc sharpenedCoverageLitProgram();

}  // namespace transparency
