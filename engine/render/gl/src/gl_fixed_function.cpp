// SPDX-License-Identifier: MIT
#include "gl_fixed_function.hpp"

#include "gl_api.hpp"

#include "gl_enums.hpp"

namespace engine::render::gl {

void applyDepthAndFaces(const PipelineDesc& desc, const ResolvedDrawState& state, bool fullscreen,
                        bool windingReversed) {
    if (state.depthTest) {
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(glCompare(state.depthFunc));
    } else {
        glDisable(GL_DEPTH_TEST);
    }
    if (!fullscreen && desc.raster.cull != CullMode::None) {
        glEnable(GL_CULL_FACE);
        glCullFace(desc.raster.cull == CullMode::Back ? GL_BACK : GL_FRONT);
    } else {
        glDisable(GL_CULL_FACE);
    }
    // With an upper-left origin GL still decides facing on NDC winding (ARB_clip_control,
    // EXT_clip_control), so counter-clockwise as displayed is GL_CCW; reversed, GL_CW.
    const bool counterClockwise = (desc.raster.frontFace == Winding::CounterClockwise) != windingReversed;
    glFrontFace(counterClockwise ? GL_CCW : GL_CW);
    glEnable(GL_SCISSOR_TEST);
}

}  // namespace engine::render::gl
