// SPDX-License-Identifier: MIT
#include "depth_restore.hpp"

#include <string>

#include "ssam_glsl.hpp"  // generated from core/glsl/
#include "gl_functions.hpp"
#include "gl_objects.hpp"
#include "shaders.hpp"

namespace ssam::gl::detail {

namespace {

// The composite's mask (§3.5.4, Listing 3.2, the same function as the composite's) against the
// threshold: below it, the opaque depth saved before the colour pass goes back. u_foliage reads
// the mask texture: the foliage colour is not needed, and rt_foliage is attached to the
// framebuffer this pass draws into (sampling it would be a feedback loop, GL 4.5 §9.3.1).
// A function, not a global: kCompositeHead is another file's global, initialised in no set order.
std::string restoreFragment() {
    return shaders::kCompositeHead + "uniform sampler2D u_opaqueDepth;\nuniform float u_threshold;\n" +
           ssam::glsl::kDepthRestoreMain;
}

bool hasStencil(int format) { return format == GL_DEPTH24_STENCIL8 || format == GL_DEPTH32F_STENCIL8; }

}  // namespace

void DepthRestore::destroy(const GlFunctions& gl) {
    if (program_) gl.DeleteProgram(program_);
    if (texture_) gl.DeleteTextures(1, &texture_);
    if (framebuffer_) gl.DeleteFramebuffers(1, &framebuffer_);
    *this = DepthRestore{};
}

void DepthRestore::saveOpaqueDepth(const GlFunctions& gl, unsigned int source, int depthFormat, int width, int height,
                                   const Rect& region) {
    if (!program_) {
        program_ =
            compileProgram(gl, "ssam::gl depth restore", shaders::kFullscreenVertex.c_str(), restoreFragment().c_str());
        composite_.locate(gl, program_);
        opaqueDepth_ = gl.GetUniformLocation(program_, "u_opaqueDepth");
        threshold_ = gl.GetUniformLocation(program_, "u_threshold");
        gl.GenFramebuffers(1, &framebuffer_);
    }
    if (width_ != width || height_ != height || format_ != depthFormat) {
        if (texture_) gl.DeleteTextures(1, &texture_);
        texture_ = 0;
        gl.GenTextures(1, &texture_);
        gl.BindTexture(GL_TEXTURE_2D, texture_);
        // A depth blit needs the same format on both sides (GL 4.5 §18.3.1).
        const GLenum format = hasStencil(depthFormat) ? GL_DEPTH_STENCIL : GL_DEPTH_COMPONENT;
        const GLenum type = depthFormat == GL_DEPTH24_STENCIL8     ? GL_UNSIGNED_INT_24_8
                            : depthFormat == GL_DEPTH32F_STENCIL8  ? GL_FLOAT_32_UNSIGNED_INT_24_8_REV
                            : depthFormat == GL_DEPTH_COMPONENT32F ? GL_FLOAT
                                                                   : GL_UNSIGNED_INT;
        gl.TexImage2D(GL_TEXTURE_2D, 0, depthFormat, width, height, 0, format, type, nullptr);
        gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
        gl.BindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer_);
        gl.FramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_TEXTURE_2D, 0, 0);
        gl.FramebufferTexture2D(GL_DRAW_FRAMEBUFFER,
                                hasStencil(depthFormat) ? GL_DEPTH_STENCIL_ATTACHMENT : GL_DEPTH_ATTACHMENT,
                                GL_TEXTURE_2D, texture_, 0);
        const GLenum none = GL_NONE;
        gl.DrawBuffers(1, &none);  // depth only: complete without a colour attachment (GL 3.3)
        gl.ReadBuffer(GL_NONE);
        checkDrawFramebuffer(gl, "depth copy");
        width_ = width, height_ = height, format_ = depthFormat;
    }
    gl.BindFramebuffer(GL_READ_FRAMEBUFFER, source);
    gl.BindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer_);
    const int x1 = region.x + region.width, y1 = region.y + region.height;
    gl.BlitFramebuffer(region.x, region.y, x1, y1, region.x, region.y, x1, y1, GL_DEPTH_BUFFER_BIT, GL_NEAREST);
}

void DepthRestore::restoreWhereMaskIsLow(const GlFunctions& gl, unsigned int target, bool hasMaskAdd,
                                         const Settings& settings) {
    gl.BindFramebuffer(GL_DRAW_FRAMEBUFFER, target);
    gl.colorMaskAt(0, GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    gl.Disable(GL_BLEND);
    gl.Enable(GL_DEPTH_TEST);  // needed for depth writes; ALWAYS: every pixel below the threshold
    gl.DepthFunc(GL_ALWAYS);
    gl.DepthMask(GL_TRUE);
    gl.UseProgram(program_);
    gl.ActiveTexture(GL_TEXTURE3);
    gl.BindTexture(GL_TEXTURE_2D, texture_);
    composite_.set(gl, 1, hasMaskAdd, settings);  // rt_foliage: the mask (see kRestoreFragment)
    gl.Uniform1i(opaqueDepth_, 3);
    gl.Uniform1f(threshold_, settings.depthMaskThreshold);
    gl.DrawArrays(GL_TRIANGLES, 0, 3);
}

}  // namespace ssam::gl::detail
