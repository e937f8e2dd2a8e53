// SPDX-License-Identifier: MIT
// GL backend: reading a texture back into floats, in bands of rows. glGetTextureSubImage
// takes the destination's size as a GLsizei, a signed 32-bit count of bytes: a 16384x16384
// RGBA16F target read as floats is 4 GiB, which would wrap it. A band is at most
// GlOptions::readbackBandBytes (never over GLsizei's range), and 8-bit textures are read
// band by band into one band-sized byte buffer, not a whole-texture copy beside the floats.
#include <algorithm>
#include <climits>
#include <cstdint>
#include <string>
#include <vector>

#include "engine/core/error.hpp"
#include "gl_backend_impl.hpp"
#include "gl_check.hpp"
#include "gl_enums.hpp"

namespace engine::render::gl {

namespace {

// Rows per band: as many whole rows as fit in `maxBandBytes` and in a GLsizei, at least one.
int rowsPerBand(std::size_t rowBytes, std::size_t maxBandBytes, int height) {
    const std::size_t limit = std::min<std::size_t>(maxBandBytes, std::size_t(INT_MAX));
    const std::size_t rows = std::max<std::size_t>(1, limit / rowBytes);
    return int(std::min<std::size_t>(rows, std::size_t(height)));
}

}  // namespace

Readback GlDriverImpl::readback(NativeId h, const TextureDesc&) {
    const GlTexture& t = textures_[h];
    const FormatInfo& info = formatInfo(t.desc.format);
    const GlFormat f = glFormat(t.desc.format);
    Readback r;
    r.width = t.desc.width;
    r.height = t.desc.height;
    r.channels = info.channels;
    r.format = t.desc.format;
    const std::size_t rowValues = std::size_t(r.width) * r.channels;
    const std::size_t values = rowValues * r.height;
    r.values.resize(values);
    makeCurrent();
    drainGlErrors();
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glPixelStorei(GL_PACK_ROW_LENGTH, 0);
    glPixelStorei(GL_PACK_SKIP_ROWS, 0);
    glPixelStorei(GL_PACK_SKIP_PIXELS, 0);
    glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    const std::string what = "readback of " + quotedName(t.desc.name);
    const bool normalized = info.isNormalized();
    const std::size_t rowBytes = rowValues * (normalized ? 1 : sizeof(float));
    const int bandRows = rowsPerBand(rowBytes, options_.readbackBandBytes, r.height);

    // Normalized formats: the stored codes / 255; sRGB is not decoded (a texture view as
    // RGBA8 reads the codes).
    GLuint source = t.id, view = 0;
    if (normalized && info.isSrgb) {
        glGenTextures(1, &view);
        glTextureView(view, GL_TEXTURE_2D, t.id, GL_RGBA8, 0, 1, 0, 1);
        checkGl(what + ": viewing the sRGB texture as RGBA8");
        source = view;
    }
    std::vector<std::uint8_t> bytes(normalized ? rowBytes * std::size_t(bandRows) : 0);
    for (int y = 0; y < r.height; y += bandRows) {
        const int rows = std::min(bandRows, r.height - y);
        const std::size_t first = std::size_t(y) * rowValues, count = std::size_t(rows) * rowValues;
        if (normalized) {
            glGetTextureSubImage(source, 0, 0, y, 0, r.width, rows, 1, f.pixelFormat, GL_UNSIGNED_BYTE, GLsizei(count),
                                 bytes.data());
            for (std::size_t i = 0; i < count; ++i) r.values[first + i] = float(bytes[i]) / 255.0f;
        } else {
            glGetTextureSubImage(source, 0, 0, y, 0, r.width, rows, 1, f.pixelFormat, GL_FLOAT,
                                 GLsizei(count * sizeof(float)), r.values.data() + first);
        }
    }
    if (view) glDeleteTextures(1, &view);
    checkGl(what);
    return r;
}

}  // namespace engine::render::gl
