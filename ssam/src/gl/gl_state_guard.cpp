// SPDX-License-Identifier: MIT
#include "gl_state_guard.hpp"

#include <epoxy/gl.h>

namespace ssam::gl {

namespace {
unsigned char isEnabled(GLenum cap) { return glIsEnabled(cap) ? 1 : 0; }
void setEnabled(GLenum cap, unsigned char on) { on ? glEnable(cap) : glDisable(cap); }
}  // namespace

GlStateGuard::GlStateGuard(bool perBufferBlend) : perBufferBlend_(perBufferBlend) {
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &drawFramebuffer_);
    glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &readFramebuffer_);
    glGetIntegerv(GL_VIEWPORT, viewport_.data());
    glGetIntegerv(GL_SCISSOR_BOX, scissorBox_.data());
    scissorTest_ = isEnabled(GL_SCISSOR_TEST);
    depthTest_ = isEnabled(GL_DEPTH_TEST);
    GLboolean depthMask = GL_TRUE;
    glGetBooleanv(GL_DEPTH_WRITEMASK, &depthMask);
    depthMask_ = depthMask ? 1 : 0;
    glGetIntegerv(GL_DEPTH_FUNC, &depthFunc_);
    cullFace_ = isEnabled(GL_CULL_FACE);
    stencilTest_ = isEnabled(GL_STENCIL_TEST);
    polygonOffsetFill_ = isEnabled(GL_POLYGON_OFFSET_FILL);
    alphaToCoverage_ = isEnabled(GL_SAMPLE_ALPHA_TO_COVERAGE);
    framebufferSrgb_ = isEnabled(GL_FRAMEBUFFER_SRGB);
    logicOp_ = isEnabled(GL_COLOR_LOGIC_OP);
    rasterizerDiscard_ = isEnabled(GL_RASTERIZER_DISCARD);
    for (GLuint i = 0; i < 2; ++i) {
        BlendTarget& b = blend_[i];
        b.enabled = glIsEnabledi(GL_BLEND, i) ? 1 : 0;
        GLboolean mask[4] = {GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE};
        glGetBooleani_v(GL_COLOR_WRITEMASK, i, mask);
        for (int c = 0; c < 4; ++c) b.colorMask[c] = mask[c] ? 1 : 0;
        if (i == 0 || perBufferBlend_) {
            // Indexed queries are GL 4.0 (per-buffer blending); buffer 0 = the global state.
            auto get = [&](GLenum what, int* value) {
                if (perBufferBlend_) glGetIntegeri_v(what, i, value);
                else glGetIntegerv(what, value);
            };
            get(GL_BLEND_EQUATION_RGB, &b.equationRgb);
            get(GL_BLEND_EQUATION_ALPHA, &b.equationAlpha);
            get(GL_BLEND_SRC_RGB, &b.srcRgb);
            get(GL_BLEND_DST_RGB, &b.dstRgb);
            get(GL_BLEND_SRC_ALPHA, &b.srcAlpha);
            get(GL_BLEND_DST_ALPHA, &b.dstAlpha);
        }
    }
    glGetIntegerv(GL_CURRENT_PROGRAM, &program_);
    glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &vertexArray_);
    glGetIntegerv(GL_ARRAY_BUFFER_BINDING, &arrayBuffer_);
    glGetIntegerv(GL_ACTIVE_TEXTURE, &activeTexture_);
    for (GLuint unit = 0; unit < textures_.size(); ++unit) {
        glActiveTexture(GL_TEXTURE0 + unit);
        glGetIntegerv(GL_TEXTURE_BINDING_2D, &textures_[unit]);
    }
    glActiveTexture(static_cast<GLenum>(activeTexture_));
    for (GLuint a = 1; a < attributes_.size(); ++a) glGetVertexAttribfv(a, GL_CURRENT_VERTEX_ATTRIB, attributes_[a].data());
}

GlStateGuard::~GlStateGuard() {
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, static_cast<GLuint>(drawFramebuffer_));
    glBindFramebuffer(GL_READ_FRAMEBUFFER, static_cast<GLuint>(readFramebuffer_));
    glViewport(viewport_[0], viewport_[1], viewport_[2], viewport_[3]);
    glScissor(scissorBox_[0], scissorBox_[1], scissorBox_[2], scissorBox_[3]);
    setEnabled(GL_SCISSOR_TEST, scissorTest_);
    setEnabled(GL_DEPTH_TEST, depthTest_);
    glDepthMask(depthMask_ ? GL_TRUE : GL_FALSE);
    glDepthFunc(static_cast<GLenum>(depthFunc_));
    setEnabled(GL_CULL_FACE, cullFace_);
    setEnabled(GL_STENCIL_TEST, stencilTest_);
    setEnabled(GL_POLYGON_OFFSET_FILL, polygonOffsetFill_);
    setEnabled(GL_SAMPLE_ALPHA_TO_COVERAGE, alphaToCoverage_);
    setEnabled(GL_FRAMEBUFFER_SRGB, framebufferSrgb_);
    setEnabled(GL_COLOR_LOGIC_OP, logicOp_);
    setEnabled(GL_RASTERIZER_DISCARD, rasterizerDiscard_);
    // Global first (all draw buffers get buffer 0's state), then buffer 1 where it can differ.
    const BlendTarget& b0 = blend_[0];
    glBlendEquationSeparate(static_cast<GLenum>(b0.equationRgb), static_cast<GLenum>(b0.equationAlpha));
    glBlendFuncSeparate(static_cast<GLenum>(b0.srcRgb), static_cast<GLenum>(b0.dstRgb), static_cast<GLenum>(b0.srcAlpha),
                        static_cast<GLenum>(b0.dstAlpha));
    if (perBufferBlend_) {
        const BlendTarget& b1 = blend_[1];
        glBlendEquationSeparatei(1, static_cast<GLenum>(b1.equationRgb), static_cast<GLenum>(b1.equationAlpha));
        glBlendFuncSeparatei(1, static_cast<GLenum>(b1.srcRgb), static_cast<GLenum>(b1.dstRgb),
                             static_cast<GLenum>(b1.srcAlpha), static_cast<GLenum>(b1.dstAlpha));
    }
    for (GLuint i = 0; i < 2; ++i) {
        const BlendTarget& b = blend_[i];
        b.enabled ? glEnablei(GL_BLEND, i) : glDisablei(GL_BLEND, i);
        glColorMaski(i, b.colorMask[0], b.colorMask[1], b.colorMask[2], b.colorMask[3]);
    }
    glUseProgram(static_cast<GLuint>(program_));
    glBindVertexArray(static_cast<GLuint>(vertexArray_));
    glBindBuffer(GL_ARRAY_BUFFER, static_cast<GLuint>(arrayBuffer_));
    for (GLuint unit = 0; unit < textures_.size(); ++unit) {
        glActiveTexture(GL_TEXTURE0 + unit);
        glBindTexture(GL_TEXTURE_2D, static_cast<GLuint>(textures_[unit]));
    }
    glActiveTexture(static_cast<GLenum>(activeTexture_));
    for (GLuint a = 1; a < attributes_.size(); ++a) glVertexAttrib4fv(a, attributes_[a].data());
}

}  // namespace ssam::gl
