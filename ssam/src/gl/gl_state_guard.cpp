// SPDX-License-Identifier: MIT
#include "gl_state_guard.hpp"

#include "gl_functions.hpp"

namespace ssam::gl::detail {

namespace {
// The generic attributes with a current value: 0 has none in a compatibility context.
GLuint firstGenericAttribute(const GlFunctions& gl) { return gl.compatibility ? 1 : 0; }
unsigned char isEnabled(const GlFunctions& gl, GLenum cap) { return gl.IsEnabled(cap) ? 1 : 0; }
void setEnabled(const GlFunctions& gl, GLenum cap, unsigned char on) { on ? gl.Enable(cap) : gl.Disable(cap); }
}  // namespace

// Desktop-only state (GL_FRAMEBUFFER_SRGB, GL_COLOR_LOGIC_OP): ES 3.0 has neither (sRGB targets
// always encode there, ES 3.0 §4.1.8), so asking would be GL_INVALID_ENUM.
void setDesktopOnly(const GlFunctions& gl, GLenum cap, bool on) {
    if (!gl.es) on ? gl.Enable(cap) : gl.Disable(cap);
}

void disableFixedFunction(const GlFunctions& gl) {
    if (!gl.compatibility) return;
    gl.Disable(kAlphaTest);
    gl.Disable(kPolygonStipple);
    if (gl.ClampColor) gl.ClampColor(kClampFragmentColor, kFixedOnly);  // the default: float targets unclamped
}

GlStateGuard::GlStateGuard(const GlFunctions& functions)
    : gl_(functions), perBufferBlend_(functions.perBufferBlend), compatibility_(functions.compatibility) {
    const GlFunctions& gl = gl_;
    gl.GetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &drawFramebuffer_);
    gl.GetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &readFramebuffer_);
    gl.GetIntegerv(GL_VIEWPORT, viewport_.data());
    gl.GetIntegerv(GL_SCISSOR_BOX, scissorBox_.data());
    scissorTest_ = isEnabled(gl, GL_SCISSOR_TEST);
    depthTest_ = isEnabled(gl, GL_DEPTH_TEST);
    GLboolean depthMask = GL_TRUE;
    gl.GetBooleanv(GL_DEPTH_WRITEMASK, &depthMask);
    depthMask_ = depthMask ? 1 : 0;
    gl.GetIntegerv(GL_DEPTH_FUNC, &depthFunc_);
    cullFace_ = isEnabled(gl, GL_CULL_FACE);
    stencilTest_ = isEnabled(gl, GL_STENCIL_TEST);
    polygonOffsetFill_ = isEnabled(gl, GL_POLYGON_OFFSET_FILL);
    alphaToCoverage_ = isEnabled(gl, GL_SAMPLE_ALPHA_TO_COVERAGE);
    if (!gl.es) {
        framebufferSrgb_ = isEnabled(gl, GL_FRAMEBUFFER_SRGB);
        logicOp_ = isEnabled(gl, GL_COLOR_LOGIC_OP);
    }
    rasterizerDiscard_ = isEnabled(gl, GL_RASTERIZER_DISCARD);
    for (GLuint i = 0; i < 2; ++i) {
        BlendTarget& b = blend_[i];
        GLboolean mask[4] = {GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE};
        if (gl.indexedBuffers) {
            b.enabled = gl.IsEnabledi(GL_BLEND, i) ? 1 : 0;
            gl.GetBooleani_v(GL_COLOR_WRITEMASK, i, mask);
        } else if (i == 0) {  // ES without per-buffer state: one for all buffers
            b.enabled = isEnabled(gl, GL_BLEND);
            gl.GetBooleanv(GL_COLOR_WRITEMASK, mask);
        }
        for (int c = 0; c < 4; ++c) b.colorMask[c] = mask[c] ? 1 : 0;
        if (i == 0 || perBufferBlend_) {
            // Indexed queries are GL 4.0 (per-buffer blending); buffer 0 = the global state.
            auto get = [&](GLenum what, int* value) {
                if (perBufferBlend_) gl.GetIntegeri_v(what, i, value);
                else gl.GetIntegerv(what, value);
            };
            get(GL_BLEND_EQUATION_RGB, &b.equationRgb);
            get(GL_BLEND_EQUATION_ALPHA, &b.equationAlpha);
            get(GL_BLEND_SRC_RGB, &b.srcRgb);
            get(GL_BLEND_DST_RGB, &b.dstRgb);
            get(GL_BLEND_SRC_ALPHA, &b.srcAlpha);
            get(GL_BLEND_DST_ALPHA, &b.dstAlpha);
        }
    }
    gl.GetIntegerv(GL_CURRENT_PROGRAM, &program_);
    gl.GetIntegerv(GL_VERTEX_ARRAY_BINDING, &vertexArray_);
    gl.GetIntegerv(GL_ARRAY_BUFFER_BINDING, &arrayBuffer_);
    gl.GetIntegerv(GL_ACTIVE_TEXTURE, &activeTexture_);
    for (GLuint unit = 0; unit < textures_.size(); ++unit) {
        gl.ActiveTexture(GL_TEXTURE0 + unit);
        gl.GetIntegerv(GL_TEXTURE_BINDING_2D, &textures_[unit]);
    }
    gl.ActiveTexture(static_cast<GLenum>(activeTexture_));
    for (GLuint a = firstGenericAttribute(gl); a < attributes_.size(); ++a)
        gl.GetVertexAttribfv(a, GL_CURRENT_VERTEX_ATTRIB, attributes_[a].data());
    if (compatibility_) {
        alphaTest_ = isEnabled(gl, kAlphaTest);
        polygonStipple_ = isEnabled(gl, kPolygonStipple);
        if (gl.ClampColor) gl.GetIntegerv(kClampFragmentColor, &clampFragmentColor_);
    }
}

GlStateGuard::~GlStateGuard() {
    const GlFunctions& gl = gl_;
    gl.BindFramebuffer(GL_DRAW_FRAMEBUFFER, static_cast<GLuint>(drawFramebuffer_));
    gl.BindFramebuffer(GL_READ_FRAMEBUFFER, static_cast<GLuint>(readFramebuffer_));
    gl.Viewport(viewport_[0], viewport_[1], viewport_[2], viewport_[3]);
    gl.Scissor(scissorBox_[0], scissorBox_[1], scissorBox_[2], scissorBox_[3]);
    setEnabled(gl, GL_SCISSOR_TEST, scissorTest_);
    setEnabled(gl, GL_DEPTH_TEST, depthTest_);
    gl.DepthMask(depthMask_ ? GL_TRUE : GL_FALSE);
    gl.DepthFunc(static_cast<GLenum>(depthFunc_));
    setEnabled(gl, GL_CULL_FACE, cullFace_);
    setEnabled(gl, GL_STENCIL_TEST, stencilTest_);
    setEnabled(gl, GL_POLYGON_OFFSET_FILL, polygonOffsetFill_);
    setEnabled(gl, GL_SAMPLE_ALPHA_TO_COVERAGE, alphaToCoverage_);
    setDesktopOnly(gl, GL_FRAMEBUFFER_SRGB, framebufferSrgb_);
    setDesktopOnly(gl, GL_COLOR_LOGIC_OP, logicOp_);
    setEnabled(gl, GL_RASTERIZER_DISCARD, rasterizerDiscard_);
    // Global first (all draw buffers get buffer 0's state), then buffer 1 where it can differ.
    const BlendTarget& b0 = blend_[0];
    gl.BlendEquationSeparate(static_cast<GLenum>(b0.equationRgb), static_cast<GLenum>(b0.equationAlpha));
    gl.BlendFuncSeparate(static_cast<GLenum>(b0.srcRgb), static_cast<GLenum>(b0.dstRgb),
                         static_cast<GLenum>(b0.srcAlpha), static_cast<GLenum>(b0.dstAlpha));
    if (perBufferBlend_) {
        const BlendTarget& b1 = blend_[1];
        gl.BlendEquationSeparatei(1, static_cast<GLenum>(b1.equationRgb), static_cast<GLenum>(b1.equationAlpha));
        gl.BlendFuncSeparatei(1, static_cast<GLenum>(b1.srcRgb), static_cast<GLenum>(b1.dstRgb),
                              static_cast<GLenum>(b1.srcAlpha), static_cast<GLenum>(b1.dstAlpha));
    }
    for (GLuint i = 0; i < 2; ++i) {
        const BlendTarget& b = blend_[i];
        if (gl.indexedBuffers) b.enabled ? gl.Enablei(GL_BLEND, i) : gl.Disablei(GL_BLEND, i);
        else if (i == 0) setEnabled(gl, GL_BLEND, b.enabled);
        gl.colorMaskAt(i, b.colorMask[0], b.colorMask[1], b.colorMask[2], b.colorMask[3]);
    }
    gl.UseProgram(static_cast<GLuint>(program_));
    gl.BindVertexArray(static_cast<GLuint>(vertexArray_));
    gl.BindBuffer(GL_ARRAY_BUFFER, static_cast<GLuint>(arrayBuffer_));
    for (GLuint unit = 0; unit < textures_.size(); ++unit) {
        gl.ActiveTexture(GL_TEXTURE0 + unit);
        gl.BindTexture(GL_TEXTURE_2D, static_cast<GLuint>(textures_[unit]));
    }
    gl.ActiveTexture(static_cast<GLenum>(activeTexture_));
    for (GLuint a = firstGenericAttribute(gl); a < attributes_.size(); ++a)
        gl.VertexAttrib4fv(a, attributes_[a].data());
    if (compatibility_) {
        setEnabled(gl, kAlphaTest, alphaTest_);
        setEnabled(gl, kPolygonStipple, polygonStipple_);
        if (gl.ClampColor) gl.ClampColor(kClampFragmentColor, static_cast<GLenum>(clampFragmentColor_));
    }
}

}  // namespace ssam::gl::detail
