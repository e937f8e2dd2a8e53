// SPDX-License-Identifier: MIT
#pragma once
// The engine-hosted SSAM's Settings::depthMaskThreshold: the depth SSAM leaves for later passes
// keeps the foliage depth only where the composited mask reaches the threshold ([Hathaway 2010]
// §3.7; core/passes.hpp's depth restore). ssam::gl and ssam::vk put the opaque depth back with a
// full-screen pass that writes depth; the engine's programs cannot write depth, so the engine-hosted
// SSAM draws the colour pass into a copy of the opaque depth and then this program into the host's:
// the foliage again, depth only, with the colour pass's surface and alpha test, discarding where
// the composited mask is below the threshold. Where the mask reaches it the host's depth is the
// colour pass's; below it, the opaque depth: the same depth as the full-screen restore.
#include "engine/render/param_block.hpp"
#include "engine/render/program.hpp"
#include "engine/render/program_desc.hpp"
#include "engine/render/texture.hpp"
#include "ssam/composite_program.hpp"

namespace ssam {

// The parameter block, declared once (engine/render/param_block.hpp): the colour pass's surface
// (MaskedLit's: its alpha is the one the alpha test sees), then the composite's mask
// (composite_program.hpp's fields), each read at the fragment's pixel, and the threshold.
#define SSAM_FOLIAGE_DEPTH_PARAMS(UNIFORM, DIRECTION, TEXTURE) \
    TEXTURE(mask, Texel, FullSize, Required)                   \
    TEXTURE(maskAdd, Texel, FullSize, Optional)                \
    UNIFORM(float, maskLerp, 0.85f)                            \
    UNIFORM(bool, squareMask, true)                            \
    UNIFORM(float, threshold, 0.0f)
ENGINE_PARAM_BLOCK_ON_LIT_SURFACE(FoliageDepthParams, SSAM_FOLIAGE_DEPTH_PARAMS);

// The colour pass's surface, the composite's mask and the threshold as one draw's parameters.
inline FoliageDepthParams foliageDepthParams(const engine::render::SurfaceParams& surface,
                                             const CompositeParams& composite, float threshold) {
    return {surface.viewProj,  surface.baseColorFactor, surface.baseColor,    surface.light, composite.mask,
            composite.maskAdd, composite.maskLerp,      composite.squareMask, threshold};
}

// Draws output alpha NaN (so any alpha test discards them) where the composited mask is below the
// threshold; elsewhere MaskedLit's colour and alpha.
engine::render::ProgramDesc foliageDepthProgram();

}  // namespace ssam
