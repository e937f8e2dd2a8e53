// SPDX-License-Identifier: MIT
#pragma once
// Saves every piece of GL state ssam::gl changes and restores it on destruction (also when the
// host's callback throws), so SSAM can run in the middle of a host's frame. The list is
// ssam/README.md's "With raw OpenGL": framebuffer bindings, viewport, scissor box and test,
// blend enable / equations / factors (draw buffers 0 and 1), colour write masks (0 and 1), depth
// test / write mask / function, face culling, stencil test, polygon offset fill,
// alpha-to-coverage, GL_FRAMEBUFFER_SRGB, colour logic op, rasterizer discard, program, vertex
// array, GL_ARRAY_BUFFER, active texture unit, the GL_TEXTURE_2D bindings of units 0-3, the
// generic vertex attributes 0-15 (0 only in core contexts: in compatibility ones it is the
// vertex position and has no current value), and in compatibility contexts alpha test, polygon
// stipple and fragment colour clamping (which the guard also switches off: disableFixedFunction).
// On OpenGL ES (Api::Gles30) there is no GL_FRAMEBUFFER_SRGB or logic op to save, and without
// per-buffer state (ES 3.0) draw buffer 0's blend enable and colour mask are every buffer's.
#include <array>

namespace ssam::gl::detail {

struct GlFunctions;

class GlStateGuard {
public:
    explicit GlStateGuard(const GlFunctions& gl);
    ~GlStateGuard();
    GlStateGuard(const GlStateGuard&) = delete;
    GlStateGuard& operator=(const GlStateGuard&) = delete;

private:
    struct BlendTarget {
        unsigned char enabled = 0;
        int equationRgb = 0, equationAlpha = 0, srcRgb = 0, dstRgb = 0, srcAlpha = 0, dstAlpha = 0;
        std::array<unsigned char, 4> colorMask{};
    };
    const GlFunctions& gl_;
    bool perBufferBlend_;
    int drawFramebuffer_ = 0, readFramebuffer_ = 0;
    std::array<int, 4> viewport_{}, scissorBox_{};
    unsigned char scissorTest_ = 0, depthTest_ = 0, depthMask_ = 0, cullFace_ = 0, stencilTest_ = 0,
                  polygonOffsetFill_ = 0, alphaToCoverage_ = 0, framebufferSrgb_ = 0, logicOp_ = 0,
                  rasterizerDiscard_ = 0;
    int depthFunc_ = 0;
    std::array<BlendTarget, 2> blend_{};
    int program_ = 0, vertexArray_ = 0, arrayBuffer_ = 0, activeTexture_ = 0;
    std::array<int, 4> textures_{};
    std::array<std::array<float, 4>, 16> attributes_{};
    bool compatibility_;
    unsigned char alphaTest_ = 0, polygonStipple_ = 0;
    int clampFragmentColor_ = 0;
};

// Enables or disables `cap` on desktop GL; nothing on ES, which has no such state.
void setDesktopOnly(const GlFunctions& gl, unsigned int cap, bool on);

// In a compatibility context, switches off the fixed-function state that would act on SSAM's
// shader output (a host's GL_ALPHA_TEST would cut the leaf edges the mask pass blends); a
// GlStateGuard made before restores it. Nothing in a core context.
void disableFixedFunction(const GlFunctions& gl);

}  // namespace ssam::gl::detail
