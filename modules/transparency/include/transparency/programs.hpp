// SPDX-License-Identifier: MIT
#pragma once
// The transparency module's own programs (weighted blended OIT and SSAM+'s composite),
// described once for every backend (engine/render/program_desc.hpp): the full-screen ones'
// parameter blocks declared once below (engine/render/param_block.hpp; WboitAccumulate's on the
// engine's lit surface), the GLSL bodies in glsl/, the CPU kernels in
// src/program_kernels.hpp.
#include <cstdint>

#include <glm/glm.hpp>

#include "engine/render/param_block.hpp"
#include "engine/render/program.hpp"
#include "engine/render/program_desc.hpp"
#include "engine/render/texture.hpp"

namespace transparency {

// WboitAccumulate (McGuire & Bavoil, "Weighted Blended Order-Independent Transparency",
// JCGT 2(2), 2013): the fragment is shaded exactly as the engine's MaskedLit program shades
// it, straight (C, a), then output premultiplied and weighted, (C * a * w, a * w), for a
// ONE/ONE additive RGBA16F accumulation target. w is the paper's eq. (7):
//   w(z, a) = a * clamp(10 / (1e-5 + (|z|/5)^2 + (|z|/200)^6), 1e-2, 3e3)
// with z the view depth (clip w; 1 under an orthographic or identity projection) times
// depthScale, which maps the scene's units onto the metres eq. (7) was tuned for.
#define TRANSPARENCY_WBOIT_ACCUMULATE_PARAMS(UNIFORM, DIRECTION, TEXTURE) UNIFORM(float, depthScale, 1.0f)
ENGINE_PARAM_BLOCK_ON_LIT_SURFACE(WboitAccumulateParams, TRANSPARENCY_WBOIT_ACCUMULATE_PARAMS);

// WboitResolve (McGuire & Bavoil 2013, the composite pass), one texel per pixel:
//   out = (accum.rgb / max(accum.a, 1e-5), revealage.r)
// blended ONE_MINUS_SRC_ALPHA / SRC_ALPHA onto the opaque colour:
//   result = average * (1 - revealage) + opaque * revealage.
// Non-finite components come out as 0 (as SSAM's composite's).
#define TRANSPARENCY_WBOIT_RESOLVE_PARAMS(UNIFORM, DIRECTION, TEXTURE)                        \
    TEXTURE(accumulation, Texel, FullSize, Required) /* RGBA16F: sum of (C * a * w, a * w) */ \
    TEXTURE(revealage, Texel, FullSize, Required)    /* r: product of (1 - a), cleared to 1 */
ENGINE_PARAM_BLOCK(WboitResolveParams, TRANSPARENCY_WBOIT_RESOLVE_PARAMS);

// How the coverage composite turns the MAX mask m and the ADD mask s (sum of the layers'
// alphas, unclamped: a float mask) into the covered fraction of the pixel, 1 - prod(1 - a_i):
enum class CoverageModel : std::uint8_t {
    // n = s / m layers all of alpha m: 1 - (1 - m)^(s / m). Exact when the layers share one
    // alpha, and exact for one layer (s = m); between the paper's MAX (too low) and ADD (too high).
    EqualLayers,
    // Many thin layers (Poisson): 1 - exp(-s).
    Exponential,
};

// CoverageComposite (SSAM+): as SSAM's composite, one texel per pixel,
//   out = (foliage.rgb, coverage(mask.r, ADD)), ADD = maskAdd.r when given, else mask.a,
// coverage clamped to [0,1] (NaN -> 0), non-finite foliage components as 0; the pipeline
// blends it SRC_ALPHA / INV_SRC_ALPHA onto the opaque colour.
// With frontLayers, (sum a * C, sum a) of the layers drawn in front of the leaf the colour pass
// kept (all of them where it kept none), the colour is the kept leaf's over their mean by the
// kept leaf's alpha k = clamp(foliage.a, 0, 1) (soft: program_kernels.hpp withFrontLayers):
//   colour * k + (front.rgb / front.a) * (1 - k), or the colour alone where front.a is not > 0.
#define TRANSPARENCY_COVERAGE_COMPOSITE_PARAMS(UNIFORM, DIRECTION, TEXTURE) \
    TEXTURE(foliage, Texel, FullSize, Required)                             \
    TEXTURE(mask, Texel, FullSize, Required)                                \
    TEXTURE(maskAdd, Texel, FullSize, Optional)                             \
    UNIFORM(CoverageModel, model, CoverageModel::EqualLayers)               \
    TEXTURE(frontLayers, Texel, FullSize, Optional)
ENGINE_PARAM_BLOCK(CoverageCompositeParams, TRANSPARENCY_COVERAGE_COMPOSITE_PARAMS);

// CoverageBlurComposite (SSAM+'s composite by default): CoverageComposite with the same
// params and coverage, its colour the 3x3 binomial (1-2-1) average of the foliage colours
// the colour pass wrote (foliage alpha > 0) around the pixel, inside the target; the pixel's
// own texel when none was written. The colour pass keeps one layer per pixel, a different one
// from pixel to pixel in a canopy; the average stands in for the blend of the layers the
// exact composite sees (measured: ssam/docs/ssam_plus.md).
//
// TransmittanceComposite (the exact reference): a premultiplied colour C and the
// transmittance T of what lies in front of the target, one texel per pixel,
//   out = (C.rgb, T), C's non-finite components as 0, T = transmittance.r clamped to [0,1]
// (NaN -> 0); the pipeline blends it ONE / SRC_ALPHA, so the target becomes C + T * target:
// "over" for a whole stack of layers at once.
#define TRANSPARENCY_TRANSMITTANCE_COMPOSITE_PARAMS(UNIFORM, DIRECTION, TEXTURE) \
    TEXTURE(color, Texel, FullSize, Required)                                    \
    TEXTURE(transmittance, Texel, FullSize, Required)
ENGINE_PARAM_BLOCK(TransmittanceCompositeParams, TRANSPARENCY_TRANSMITTANCE_COMPOSITE_PARAMS);

// For Backend::createProgram. Full-screen inputs must be at least the target's size; the
// coverage model must be one of the above.
engine::render::ProgramDesc wboitAccumulateProgram();
engine::render::ProgramDesc wboitResolveProgram();
engine::render::ProgramDesc coverageCompositeProgram();
engine::render::ProgramDesc coverageBlurCompositeProgram();  // CoverageCompositeParams
engine::render::ProgramDesc transmittanceCompositeProgram();

}  // namespace transparency
