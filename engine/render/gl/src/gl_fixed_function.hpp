// SPDX-License-Identifier: MIT
#pragma once
// A draw's depth test and face culling as GL state, the same calls on OpenGL 4.5 and ES 3.0
// (the GL and GLES drivers share them).
#include "engine/render/pipeline.hpp"
#include "engine/render/resolved_draw_state.hpp"

namespace engine::render::gl {

// Depth test and function, culling (never for full-screen programs, whose triangle the soft
// backend never culls), the front face, and the scissor test switched on. `windingReversed`:
// the vertex stage flips y under a lower-left origin (the GLES driver without EXT_clip_control),
// so the displayed winding is the opposite of GL's.
void applyDepthAndFaces(const PipelineDesc& desc, const ResolvedDrawState& state, bool fullscreen,
                        bool windingReversed = false);

}  // namespace engine::render::gl
