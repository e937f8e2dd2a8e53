// SPDX-License-Identifier: MIT
#pragma once
// The HUD's two programs, described once for every backend (engine/render/program_desc.hpp;
// parameter blocks declared once below, engine/render/param_block.hpp; GLSL bodies in glsl/,
// CPU kernels in overlay_kernels.hpp):
//   OverlayFill  (Mesh): out = the vertex colour (straight alpha), for panels and glyph
//                quads given in pixels and mapped to clip space by `viewProj`;
//   OverlayPanel (full screen, drawn under a scissor): out = the texel of `source` at
//                sourceOrigin + floor((pixel - targetOrigin) / zoom), alpha 1: a region of
//                another image copied, or zoomed by a whole factor (the compare's split
//                and insets). A texel outside the source is black.
#include <glm/glm.hpp>

#include "engine/render/param_block.hpp"
#include "engine/render/program_desc.hpp"
#include "engine/render/texture.hpp"

namespace hud {

#define HUD_OVERLAY_FILL_PARAMS(UNIFORM, DIRECTION, TEXTURE) UNIFORM(glm::mat4, viewProj, glm::mat4(1.0f))
ENGINE_PARAM_BLOCK(OverlayFillParams, HUD_OVERLAY_FILL_PARAMS);

#define HUD_OVERLAY_PANEL_PARAMS(UNIFORM, DIRECTION, TEXTURE)                                                 \
    TEXTURE(source, Texel, Sampled, Required) /* single-sampled colour */                                     \
    UNIFORM(int, sourceX, 0)                  /* texel at targetX, targetY (x/y from the top-left, y down) */ \
    UNIFORM(int, sourceY, 0)                                                                                  \
    UNIFORM(int, targetX, 0)                                                                                  \
    UNIFORM(int, targetY, 0)                                                                                  \
    UNIFORM(int, zoom, 1) /* 1..64 */
ENGINE_PARAM_BLOCK(OverlayPanelParams, HUD_OVERLAY_PANEL_PARAMS);

// Pixel coordinates (x right, y down from the top-left corner, z 0.5) to clip space for a
// width x height target: what OverlayFill's viewProj is.
glm::mat4 pixelToClip(int width, int height);

engine::render::ProgramDesc overlayFillProgram();
engine::render::ProgramDesc overlayPanelProgram();  // draws are checked: zoom in 1..64

}  // namespace hud
