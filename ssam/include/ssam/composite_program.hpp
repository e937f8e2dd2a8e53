// SPDX-License-Identifier: MIT
#pragma once
// SSAM's composite ([Hathaway 2010] §3.5.4, Listing 3.2), full screen, one texel per pixel:
//   mask = lerp(mask.r (MAX), ADD, maskLerp), clamped to [0, 1] (NaN -> 0), squared when
//          squareMask (the squared alpha trick, §3.6.2); ADD = maskAdd.r when given, else mask.a
//   out  = (foliage.rgb, mask), non-finite foliage components output as 0; with colorFade.y >
//          colorFade.x (Settings::colorFade) foliage.rgb is mix(foliageClear, foliage.rgb,
//          smoothstep(colorFade.x, colorFade.y, MAX mask)); with colorBlur foliage.rgb is first the
//          1-2-1 3x3 average of the written (alpha > 0) foliage texels around the pixel inside the
//          target, the pixel's own where none was written
// The pipeline blends it onto the opaque colour with SRC_ALPHA / INV_SRC_ALPHA, which is
// Listing 3.2's lerp(opaque, foliage, mask) done by the blend unit, as §3.5 describes the
// post-process ("resembles frame-buffer blending ... SRCALPHA and INVSRCALPHA"). Composing in
// place lets a scissor limit the work to the foliage's screen bounds.
// One GLSL source serves both the engine backend's program and ssam::gl (ssam/src/core/glsl/composite*.glsl).
#include "engine/render/param_block.hpp"
#include "engine/render/program_desc.hpp"
#include "engine/render/texture.hpp"

namespace ssam {

// The parameter block, declared once (engine/render/param_block.hpp): the struct, its uniform and
// texture table (every texture read at every target pixel: at least the target's size) and the
// names the GLSL reads (u_maskAddBound: whether maskAdd is given).
#define SSAM_COMPOSITE_PARAMS(UNIFORM, DIRECTION, TEXTURE)                                                         \
    TEXTURE(foliage, Texel, FullSize, Required)                                                                    \
    TEXTURE(mask, Texel, FullSize, Required)    /* r = MAX mask, a = ADD mask (one RGBA target) */                 \
    TEXTURE(maskAdd, Texel, FullSize, Optional) /* ADD mask in its own R target (then `mask` holds MAX in r) */    \
    UNIFORM(float, maskLerp, 0.85f)                                                                                \
    UNIFORM(bool, squareMask, true)                                                                                \
    UNIFORM(glm::vec2, colorFade, glm::vec2(0.0f))    /* core::ColorFade's (start, end); off unless end > start */ \
    UNIFORM(glm::vec3, foliageClear, glm::vec3(0.0f)) /* the colour it fades from */                               \
    UNIFORM(bool, colorBlur, false)                   /* Settings::colorBlur */
ENGINE_PARAM_BLOCK(CompositeParams, SSAM_COMPOSITE_PARAMS);

// For Backend::createProgram. Draws are checked for: foliage and mask textures of at least the
// target's size (and maskAdd when given), a finite maskLerp.
engine::render::ProgramDesc compositeProgram();

}  // namespace ssam
