// SPDX-License-Identifier: MIT
// GLES driver: showing a finished frame in the context's window (the web page's canvas), row 0
// at the top as every target of this driver stores it.
//
// Why a copy for sRGB frames: an ES 3.0 blit decodes an sRGB read buffer to linear and encodes
// only into an sRGB draw buffer (OpenGL ES 3.0 §4.3.3), and a window's (WebGL's canvas's) default
// framebuffer is linear, so a blit would show the decoded values. The stored codes are copied as
// they are instead, on the GPU: glReadPixels into a pixel buffer, that buffer uploaded into a
// linear RGBA8 texture, which is blitted. The window then shows the bytes a capture holds, as the
// GL 4.5 driver's present does with GL_FRAMEBUFFER_SRGB off.
#include <string>

#include "engine/render/format.hpp"
#include "gl_check.hpp"
#include "gles_driver.hpp"

namespace engine::render::gles {

GLuint GlesDriver::linearCopy(const GlTexture& t, const std::string& what) {
    const int width = t.desc.width, height = t.desc.height;
    if (!presentCopy_.texture || presentCopy_.width != width || presentCopy_.height != height) {
        if (presentCopy_.texture) {
            framebuffers_.forget(presentCopy_.texture);
            glDeleteTextures(1, &presentCopy_.texture);
        }
        if (!presentCopy_.pixels) glGenBuffers(1, &presentCopy_.pixels);
        glBindBuffer(GL_PIXEL_PACK_BUFFER, presentCopy_.pixels);
        glBufferData(GL_PIXEL_PACK_BUFFER, GLsizeiptr(width) * height * 4, nullptr, GL_STREAM_COPY);
        glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
        glGenTextures(1, &presentCopy_.texture);
        glBindTexture(GL_TEXTURE_2D, presentCopy_.texture);
        glTexStorage2D(GL_TEXTURE_2D, 1, GL_RGBA8, width, height);
        presentCopy_.width = width;
        presentCopy_.height = height;
    }
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffers_.get({attachment(t)}, 0, what));
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glBindBuffer(GL_PIXEL_PACK_BUFFER, presentCopy_.pixels);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, presentCopy_.pixels);
    glBindTexture(GL_TEXTURE_2D, presentCopy_.texture);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
    return presentCopy_.texture;
}

bool GlesDriver::present(NativeId h, const TextureDesc&) {
    const GlTexture& t = textures_[h];
    if (!context_ || !context_->hasWindow()) return false;
    const glm::ivec2 size = context_->framebufferSize();
    if (size.x <= 0 || size.y <= 0) return false;  // minimised: nothing to show
    makeCurrent();
    gl::drainGlErrors();
    const std::string what = "present of " + quotedName(t.desc.name);
    const GLuint shown = formatInfo(t.desc.format).isSrgb ? linearCopy(t, what) : attachment(t);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffers_.get({shown}, 0, what));
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    glDisable(GL_SCISSOR_TEST);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    const bool same = size.x == t.desc.width && size.y == t.desc.height;
    // Row 0 at the top of the window: the default framebuffer's row 0 is its bottom.
    glBlitFramebuffer(0, 0, t.desc.width, t.desc.height, 0, size.y, size.x, 0, GL_COLOR_BUFFER_BIT,
                      same ? GL_NEAREST : GL_LINEAR);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    gl::checkGl(what);
    context_->swapBuffers();
    return true;
}

}  // namespace engine::render::gles
