// SPDX-License-Identifier: MIT
// GLES driver: textures (immutable storage) and multisampled renderbuffers, their uploads and
// fills with the soft driver's bits, buffers, programs, pipelines and occlusion queries.
#include <algorithm>
#include <string>
#include <utility>

#include "engine/core/error.hpp"
#include "engine/core/log.hpp"
#include "engine/render/gl/gl_program.hpp"
#include "engine/render/texel_codec.hpp"
#include "gl_check.hpp"
#include "gl_enums.hpp"
#include "gl_shaders.hpp"
#include "gles_driver.hpp"
#include "gl_upload.hpp"
#include "gles_shaders.hpp"

namespace engine::render::gles {

using gl::checkGl;
using gl::drainGlErrors;
using gl::glFormat;
using gl::GlFormat;

GLuint makeBoundFramebuffer(const std::vector<GLuint>& colors, GLuint depth, const std::string& what) {
    GLuint fbo = 0;
    glGenFramebuffers(1, &fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    auto attach = [](GLenum point, GLuint name) {
        if (name & kRenderbufferBit)
            glFramebufferRenderbuffer(GL_FRAMEBUFFER, point, GL_RENDERBUFFER, name & ~kRenderbufferBit);
        else glFramebufferTexture2D(GL_FRAMEBUFFER, point, GL_TEXTURE_2D, name, 0);
    };
    std::vector<GLenum> drawBuffers;
    for (std::size_t i = 0; i < colors.size(); ++i) {
        attach(GLenum(GL_COLOR_ATTACHMENT0 + i), colors[i]);
        drawBuffers.push_back(GLenum(GL_COLOR_ATTACHMENT0 + i));
    }
    if (depth) attach(GL_DEPTH_ATTACHMENT, depth);
    if (drawBuffers.empty()) drawBuffers.push_back(GL_NONE);
    glDrawBuffers(GLsizei(drawBuffers.size()), drawBuffers.data());
    glReadBuffer(colors.empty() ? GL_NONE : GL_COLOR_ATTACHMENT0);
    const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    if (status != GL_FRAMEBUFFER_COMPLETE) {
        glDeleteFramebuffers(1, &fbo);
        throw Error(what + ": framebuffer incomplete (" + gl::framebufferStatusName(status) + ")");
    }
    return fbo;
}

GLuint GlesDriver::attachment(const GlTexture& t) const {
    return t.desc.samples > 1 ? (t.id | kRenderbufferBit) : t.id;
}

void GlesDriver::checkTexture(const TextureDesc& desc, const TextureData* data, const std::string& what) {
    const FormatInfo& info = formatInfo(desc.format);
    // ES 3.0 renders to no float format (§3.8.3 Table 3.13); EXT_color_buffer_float adds them.
    if ((desc.usage & UsageRenderTarget) && !info.isDepth && !info.isNormalized() && !extensions_.colorBufferFloat)
        throw Error(what + ": rendering to " + std::string(formatName(desc.format)) +
                    " needs GL_EXT_color_buffer_float, which " + renderer_ + " lacks");
    if (desc.samples > 1) {
        const int supported = maxSamplesFor(glFormat(desc.format).internal);
        if (desc.samples > supported)
            throw Error(what + ": " + std::to_string(desc.samples) + " samples exceed this GLES implementation's " +
                        std::to_string(supported) + " for " + std::string(formatName(desc.format)) + " (" + renderer_ +
                        ")");
        if (data && !data->levels.empty())
            throw Error(what + ": initial data for a multisampled texture (a renderbuffer on OpenGL ES 3.0)");
    }
    gl::checkGlTextureFits(desc, what, textureLimits_);
}

NativeId GlesDriver::createTexture(const TextureDesc& desc, const TextureData* data, const std::string& what) {
    const GlFormat f = glFormat(desc.format);
    GlTexture t{desc};
    makeCurrent();
    drainGlErrors();
    if (desc.samples > 1) {
        glGenRenderbuffers(1, &t.id);
        glBindRenderbuffer(GL_RENDERBUFFER, t.id);
        glRenderbufferStorageMultisample(GL_RENDERBUFFER, desc.samples, f.internal, desc.width, desc.height);
        GLint samples = 0;
        glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_SAMPLES, &samples);
        glBindRenderbuffer(GL_RENDERBUFFER, 0);
        t.actualSamples = std::max(1, int(samples));
    } else {
        glGenTextures(1, &t.id);
        glBindTexture(GL_TEXTURE_2D, t.id);
        glTexStorage2D(GL_TEXTURE_2D, desc.mipLevels, f.internal, desc.width, desc.height);
        // A texture's own filters apply where no sampler object is bound: the texelFetch reads
        // (TextureRead::Texel) and the depth readback. texelFetch ignores them, but completeness
        // does not (ES 3.0 §3.8.13): a depth texture under the default LINEAR filters is
        // incomplete and every read of it returns 0 (ANGLE holds to this, llvmpipe does not).
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    }
    try {
        checkGl(what + ": allocating " + std::to_string(desc.width) + "x" + std::to_string(desc.height) + " " +
                std::string(formatName(desc.format)));
        // ES leaves new storage undefined; the soft backend starts from zero bytes.
        if (data && !data->levels.empty()) upload(t, *data);
        else fill(t, glm::vec4(0.0f));
        checkGl(what + ": initialising");
    } catch (...) {
        deleteStorage(t);
        throw;
    }
    return textures_.add(std::move(t));
}

void GlesDriver::upload(const GlTexture& t, const TextureData& data) {
    const GlFormat f = glFormat(t.desc.format);
    glBindTexture(GL_TEXTURE_2D, t.id);
    gl::uploadLevels(t.desc, data, [&](int level, int w, int h, const std::byte* stored) {
        glTexSubImage2D(GL_TEXTURE_2D, level, 0, 0, w, h, f.pixelFormat, f.storedType, stored);
    });
}

// ES 3.0 has no glClearTexImage, and glClearBuffer converts with the implementation's rounding
// (llvmpipe: UNORM ties to even, halves toward zero): single-sampled textures are filled by an
// upload of the soft backend's encoding of the value, bit for bit. A renderbuffer cannot be
// uploaded to: it is cleared by glClearBuffer, exact for 0 and 1 (the values passes clear to
// in practice), within the implementation's rounding otherwise.
void GlesDriver::fill(const GlTexture& t, const glm::vec4& value) {
    const std::vector<std::byte> texel = encodeTexel(t.desc.format, value);
    if (t.desc.samples == 1) {
        fillLevels(t, value == glm::vec4(0.0f) ? t.desc.mipLevels : 1, texel);
        return;
    }
    const GLuint fbo = formatInfo(t.desc.format).isDepth ? framebuffers_.get({}, attachment(t), "clear")
                                                         : framebuffers_.get({attachment(t)}, 0, "clear");
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_RASTERIZER_DISCARD);
    if (formatInfo(t.desc.format).isDepth) {
        glDepthMask(GL_TRUE);
        glClearBufferfv(GL_DEPTH, 0, &value.x);
    } else {
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        glClearBufferfv(GL_COLOR, 0, &value.x);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void GlesDriver::fillLevels(const GlTexture& t, int levels, const std::vector<std::byte>& texel) {
    const GlFormat f = glFormat(t.desc.format);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
    glBindTexture(GL_TEXTURE_2D, t.id);
    std::vector<std::byte> texels;
    for (int level = 0; level < levels; ++level) {
        const int w = std::max(1, t.desc.width >> level), h = std::max(1, t.desc.height >> level);
        const std::size_t count = std::size_t(w) * h;
        if (texels.size() != count * texel.size()) {
            texels.resize(count * texel.size());
            for (std::size_t i = 0; i < count; ++i)
                std::copy(texel.begin(), texel.end(), texels.begin() + i * texel.size());
        }
        glTexSubImage2D(GL_TEXTURE_2D, level, 0, 0, w, h, f.pixelFormat, f.storedType, texels.data());
    }
}

NativeId GlesDriver::createBuffer(const BufferDesc& desc, std::span<const std::byte> data, const std::string& what) {
    if (desc.size > (std::uint64_t(1) << 31) - 1)
        throw Error(what + ": " + std::to_string(desc.size >> 20) + " MiB exceeds the GLES backend's 2 GiB limit");
    makeCurrent();
    drainGlErrors();
    GlBuffer b;
    std::vector<std::byte> zeros;
    if (data.empty()) zeros.assign(desc.size, std::byte{0});
    glGenBuffers(1, &b.id);
    // An index buffer is written through the element binding of no vertex array of ours (0).
    if (desc.kind == BufferKind::Index) {
        b.uploadTarget = GL_ELEMENT_ARRAY_BUFFER;
        glBindVertexArray(0);
    }
    glBindBuffer(b.uploadTarget, b.id);
    glBufferData(b.uploadTarget, GLsizeiptr(desc.size), data.empty() ? zeros.data() : data.data(), GL_DYNAMIC_DRAW);
    glBindBuffer(b.uploadTarget, 0);
    try {
        checkGl(what + ": allocating " + std::to_string(desc.size) + " bytes");
    } catch (...) {
        glDeleteBuffers(1, &b.id);
        throw;
    }
    return buffers_.add(std::move(b));
}

void GlesDriver::updateBuffer(NativeId handle, std::uint64_t offset, std::span<const std::byte> data) {
    makeCurrent();
    const GlBuffer& b = buffers_[handle];
    if (b.uploadTarget == GL_ELEMENT_ARRAY_BUFFER) glBindVertexArray(0);
    glBindBuffer(b.uploadTarget, b.id);
    glBufferSubData(b.uploadTarget, GLintptr(offset), GLsizeiptr(data.size()), data.data());
    glBindBuffer(b.uploadTarget, 0);
}

GlesProgram GlesDriver::compile(std::shared_ptr<const ProgramDesc> desc) {
    makeCurrent();
    const std::string name = desc->name;
    GlesProgram p;
    const bool remap = !extensions_.clipControl;
    p.slot = gl::compileSlot(std::move(desc), [&name, remap](std::string source, GLenum stage) {
        return glslEs(std::move(source), name, remap && stage == GL_VERTEX_SHADER);
    });
    bindSamplerUnits(p.slot->program.id(), p.slot->desc->gl);
    for (const TextureField& t : p.slot->desc->gl.textures)
        p.levels.push_back(p.slot->program.uniform(levelsUniform(t.name).c_str()));
    return p;
}

NativeId GlesDriver::createProgram(std::shared_ptr<const ProgramDesc> desc) {
    if (desc->gl.fragment.empty())
        throw Error("program " + quotedName(desc->name) + " has no GLSL for the GLES backend");
    return programs_.add(compile(std::move(desc)));
}

NativeId GlesDriver::createStandardProgram(ProgramKind kind, ProgramDesc desc) {
    desc.gl.fragment = gl::standardFragment(kind);
    return programs_.add(compile(std::make_shared<const ProgramDesc>(std::move(desc))));
}

void GlesDriver::notePipeline(const PipelineDesc& desc, ResolvedPipeline& resolved) {
    PipelineInfo& info = resolved.info;
    if (desc.alphaTest.alphaToCoverage) {
        info.exact = false;
        info.note += std::string(info.note.empty() ? "" : "; ") +
                     "OpenGL ES 3.0 has no gl_SampleMask: GL_SAMPLE_ALPHA_TO_COVERAGE, whose coverage pattern is "
                     "implementation-defined";
    }
    if (!info.exact) log::debug("GLES pipeline ", quotedName(desc.name), ": inexact emulation: ", info.note);
}

void GlesDriver::deleteStorage(const GlTexture& t) {
    if (t.desc.samples > 1) glDeleteRenderbuffers(1, &t.id);
    else glDeleteTextures(1, &t.id);
}

void GlesDriver::destroyTexture(NativeId h) {
    makeCurrent();
    framebuffers_.forget(attachment(textures_[h]));
    deleteStorage(textures_[h]);
    textures_.remove(h);
}

// Buffers, programs and queries: their GL objects go with their slots.
void GlesDriver::destroyBuffer(NativeId h) {
    makeCurrent();
    glDeleteBuffers(1, &buffers_[h].id);
    buffers_.remove(h);
}

void GlesDriver::destroyProgram(NativeId h) {
    makeCurrent();
    programs_.remove(h);
}

void GlesDriver::destroyQuery(NativeId h) {
    makeCurrent();
    if (queries_[h].id) glDeleteQueries(1, &queries_[h].id);
    queries_.remove(h);
}

bool GlesDriver::anySamplesPassed(NativeId h) {
    makeCurrent();
    return queries_[h].id && samplesPassed(queries_[h].id);
}

// Natively the result is waited for, as GL_QUERY_WAIT would on the GPU: the same answer as the
// other drivers. A browser cannot wait: WebGL 2.0 (§3.7.12, getQueryParameter) makes no result
// available before control returns to the browser, and asking for it earlier answers nothing.
// There an unknown result counts as samples passed, as GL_QUERY_NO_WAIT lets a GPU render
// (OpenGL 4.6 §10.9 "Conditional Rendering"): the light shafts' glow is drawn whenever the sun's
// visibility is not yet known, where natively it is skipped behind a hidden sun.
bool GlesDriver::samplesPassed(GLuint id) {
#if defined(__EMSCRIPTEN__)
    GLuint available = 0;
    glGetQueryObjectuiv(id, GL_QUERY_RESULT_AVAILABLE, &available);
    if (!available) return true;
#endif
    GLuint any = 0;
    glGetQueryObjectuiv(id, GL_QUERY_RESULT, &any);
    return any != 0;
}

int GlesDriver::maxSamplesFor(GLenum internal) {
    auto it = maxSamplesByFormat_.find(internal);
    if (it != maxSamplesByFormat_.end()) return it->second;
    makeCurrent();
    return maxSamplesByFormat_[internal] = gl::maxSamplesOf(GL_RENDERBUFFER, internal);
}

}  // namespace engine::render::gles
