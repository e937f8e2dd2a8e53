// SPDX-License-Identifier: MIT
#pragma once
// The HUD's two programs, described once for every backend (engine/render/program_desc.hpp;
// GLSL in overlay_programs.cpp, CPU kernels in overlay_kernels.hpp):
//   OverlayFill  (Mesh): out = the vertex colour (straight alpha), for panels and glyph
//                quads given in pixels and mapped to clip space by `viewProj`;
//   OverlayPanel (full screen, drawn under a scissor): out = the texel of `source` at
//                sourceOrigin + floor((pixel - targetOrigin) / zoom), alpha 1: a region of
//                another image copied, or zoomed by a whole factor (the compare's split
//                and insets). A texel outside the source is black.
#include <glm/glm.hpp>

#include "engine/render/program_desc.hpp"
#include "engine/render/texture.hpp"

namespace hud {

struct OverlayFillParams {
    glm::mat4 viewProj{1.0f};
};

struct OverlayPanelParams {
    engine::render::TextureHandle source;  // single-sampled colour
    int sourceX = 0, sourceY = 0;          // texel at targetX, targetY (x/y from the top-left, y down)
    int targetX = 0, targetY = 0;
    int zoom = 1;  // 1..64
};

// Pixel coordinates (x right, y down from the top-left corner, z 0.5) to clip space for a
// width x height target: what OverlayFill's viewProj is.
glm::mat4 pixelToClip(int width, int height);

engine::render::ProgramDesc overlayFillProgram();
engine::render::ProgramDesc overlayPanelProgram();  // draws are checked: zoom in 1..64

}  // namespace hud
