// SPDX-License-Identifier: MIT
// GLES driver: reading a texture back. ES 3.0 has no glGetTexImage: colour is read with
// glReadPixels from a framebuffer (as RGBA, the one layout §4.3.2 guarantees for every colour
// format: bytes for normalized, floats for float targets, the stored codes of sRGB); depth,
// which glReadPixels cannot read on ES, is copied texel for texel into an R32F target first.
#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "engine/core/error.hpp"
#include "engine/render/gl/gl_program.hpp"
#include "gl_check.hpp"
#include "gl_shaders.hpp"
#include "gles_driver.hpp"
#include "gles_shaders.hpp"

namespace engine::render::gles {

using gl::checkGl;

namespace {

constexpr std::size_t kBandBytes = std::size_t(1) << 28;  // RGBA rows read per glReadPixels, at most

}  // namespace

Readback GlesDriver::readback(NativeId h, const TextureDesc&) {
    const GlTexture& t = textures_[h];
    const FormatInfo& info = formatInfo(t.desc.format);
    const std::string what = "readback of " + quotedName(t.desc.name);
    Readback r{t.desc.width, t.desc.height, info.channels, t.desc.format, {}};
    r.values.resize(std::size_t(r.width) * r.height * r.channels);
    makeCurrent();
    gl::drainGlErrors();

    GLuint source = t.id, copy = 0;
    if (info.isDepth) {
        if (!extensions_.colorBufferFloat)
            throw Error(what +
                        ": reading depth back on OpenGL ES 3.0 renders it to R32F, which needs "
                        "GL_EXT_color_buffer_float (" +
                        renderer_ + " lacks it)");
        if (!depthToColor_) {
            depthToColor_.emplace();
            depthToColor_->program = gl::compileProgram(
                "depth readback", glslEs(gl::fullscreenVertexSource(), "depth readback", !extensions_.clipControl),
                depthToColorFragmentSource());
        }
        glGenTextures(1, &copy);
        glBindTexture(GL_TEXTURE_2D, copy);
        glTexStorage2D(GL_TEXTURE_2D, 1, GL_R32F, r.width, r.height);
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffers_.get({copy}, 0, what));
        applyBaseState();
        glViewport(0, 0, r.width, r.height);
        glDisable(GL_SCISSOR_TEST);
        glDisable(GL_DEPTH_TEST);
        glDisable(GL_CULL_FACE);
        glDisable(GL_BLEND);
        glDisable(GL_SAMPLE_ALPHA_TO_COVERAGE);
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        glUseProgram(depthToColor_->program.id());
        glActiveTexture(GL_TEXTURE0);
        glBindTexture(GL_TEXTURE_2D, t.id);
        glBindSampler(0, 0);
        glBindVertexArray(emptyVao_);
        glDrawArrays(GL_TRIANGLES, 0, 3);
        source = copy;
    }
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffers_.get({source}, 0, what));
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glPixelStorei(GL_PACK_ROW_LENGTH, 0);
    glPixelStorei(GL_PACK_SKIP_ROWS, 0);
    glPixelStorei(GL_PACK_SKIP_PIXELS, 0);
    glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    const bool normalized = info.isNormalized();
    const std::size_t rowBytes = std::size_t(r.width) * 4 * (normalized ? 1 : sizeof(float));
    const int bandRows = int(std::clamp<std::size_t>(kBandBytes / rowBytes, 1, std::size_t(r.height)));
    std::vector<std::uint8_t> bytes(normalized ? rowBytes * bandRows : 0);
    std::vector<float> floats(normalized ? 0 : rowBytes * bandRows / sizeof(float));
    const int channels = r.channels;
    for (int y = 0; y < r.height; y += bandRows) {
        const int rows = std::min(bandRows, r.height - y);
        if (normalized) glReadPixels(0, y, r.width, rows, GL_RGBA, GL_UNSIGNED_BYTE, bytes.data());
        else glReadPixels(0, y, r.width, rows, GL_RGBA, GL_FLOAT, floats.data());
        const std::size_t pixels = std::size_t(r.width) * rows;
        float* out = r.values.data() + std::size_t(y) * r.width * channels;
        for (std::size_t p = 0; p < pixels; ++p)
            for (int c = 0; c < channels; ++c)
                out[p * channels + c] = normalized ? float(bytes[p * 4 + c]) / 255.0f : floats[p * 4 + c];
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    if (copy) {
        framebuffers_.forget(copy);
        glDeleteTextures(1, &copy);
    }
    checkGl(what);
    return r;
}

}  // namespace engine::render::gles
