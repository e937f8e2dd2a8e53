// SPDX-License-Identifier: MIT
// GL driver: textures (storage, upload, clears to the soft driver's bits), buffers, programs,
// pipelines (how each will emulate the alpha test's fail modes) and occlusion queries.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <utility>

#include "engine/core/error.hpp"
#include "engine/core/log.hpp"
#include "gl_backend_impl.hpp"
#include "gl_check.hpp"
#include "gl_enums.hpp"
#include "gl_shaders.hpp"
#include "gl_upload.hpp"
#include "engine/render/texel_codec.hpp"

namespace engine::render::gl {

void GlDriverImpl::checkTexture(const TextureDesc& desc, const TextureData* data, const std::string& what) {
    if (desc.samples > 1) {
        const int supported = maxSamplesFor(glFormat(desc.format).internal);
        if (desc.samples > supported)
            throw Error(what + ": " + std::to_string(desc.samples) + " samples exceed this GL implementation's " +
                        std::to_string(supported) + " for " + std::string(formatName(desc.format)) + " (" +
                        info_.renderer + ")");
        if (data && !data->levels.empty())
            throw Error(what + ": initial data for a multisampled texture (the GL backend cannot upload samples)");
    }
    checkGlTextureFits(desc, what, textureLimits_);
}

// A GPU's figure is read through GL, so with the driver's context current.
MemoryProbe GlDriverImpl::memoryProbe() const {
    if (!textureLimits_.memory) return {};
    return [this]() {
        if (context_) context_->makeCurrent();
        return textureLimits_.memory();
    };
}

NativeId GlDriverImpl::createTexture(const TextureDesc& desc, const TextureData* data, const std::string& what) {
    const GlFormat f = glFormat(desc.format);
    makeCurrent();
    drainGlErrors();
    GlTexture t;
    t.desc = desc;
    if (desc.samples > 1) {
        glCreateTextures(GL_TEXTURE_2D_MULTISAMPLE, 1, &t.id);
        glTextureStorage2DMultisample(t.id, desc.samples, f.internal, desc.width, desc.height, GL_TRUE);
        GLint samples = 0;
        glGetTextureLevelParameteriv(t.id, 0, GL_TEXTURE_SAMPLES, &samples);
        t.actualSamples = std::max(1, int(samples));
    } else {
        glCreateTextures(GL_TEXTURE_2D, 1, &t.id);
        glTextureStorage2D(t.id, desc.mipLevels, f.internal, desc.width, desc.height);
    }
    try {
        checkGl(what + ": allocating " + std::to_string(desc.width) + "x" + std::to_string(desc.height) + " " +
                std::string(formatName(desc.format)));
        if (data && !data->levels.empty()) upload(t, *data);
        else clearToZero(t);
        checkGl(what + ": initialising");
    } catch (...) {
        glDeleteTextures(1, &t.id);
        throw;
    }
    ownedTextures_.insert(t.id);
    return textures_.add(std::move(t));
}

NativeId GlDriverImpl::wrapTexture(unsigned int id, const TextureDesc& desc, const std::string& what) {
    makeCurrent();
    drainGlErrors();
    if (!glIsTexture(id)) throw Error(what + ": GL name " + std::to_string(id) + " is not a texture");
    GLint target = 0, width = 0, height = 0, samples = 0, internal = 0, levels = 0;
    glGetTextureParameteriv(id, GL_TEXTURE_TARGET, &target);
    glGetTextureLevelParameteriv(id, 0, GL_TEXTURE_WIDTH, &width);
    glGetTextureLevelParameteriv(id, 0, GL_TEXTURE_HEIGHT, &height);
    glGetTextureLevelParameteriv(id, 0, GL_TEXTURE_SAMPLES, &samples);
    glGetTextureLevelParameteriv(id, 0, GL_TEXTURE_INTERNAL_FORMAT, &internal);
    glGetTextureParameteriv(id, GL_TEXTURE_IMMUTABLE_LEVELS, &levels);
    checkGl(what + ": querying GL texture " + std::to_string(id));
    const GLenum expectedTarget = desc.samples > 1 ? GL_TEXTURE_2D_MULTISAMPLE : GL_TEXTURE_2D;
    if (GLenum(target) != expectedTarget)
        throw Error(what + ": GL texture " + std::to_string(id) + " is not a " +
                    (desc.samples > 1 ? "2D multisample" : "2D") + " texture");
    if (width != desc.width || height != desc.height)
        throw Error(what + ": GL texture is " + std::to_string(width) + "x" + std::to_string(height) +
                    ", described as " + std::to_string(desc.width) + "x" + std::to_string(desc.height));
    if (desc.samples > 1 && samples < desc.samples)
        throw Error(what + ": GL texture has " + std::to_string(samples) + " samples, described with " +
                    std::to_string(desc.samples));
    if (GLenum(internal) != glFormat(desc.format).internal)
        throw Error(what + ": GL internal format " + hex(unsigned(internal)) + " is not " +
                    std::string(formatName(desc.format)));
    GlTexture t;
    t.desc = desc;
    t.id = id;
    t.actualSamples = desc.samples > 1 ? samples : 1;
    t.imported = true;
    return textures_.add(std::move(t));
}

NativeId GlDriverImpl::createBuffer(const BufferDesc& desc, std::span<const std::byte> data, const std::string& what) {
    if (desc.size > (std::uint64_t(1) << 32))
        throw Error(what + ": " + std::to_string(desc.size >> 20) + " MiB exceeds the GL backend's 4 GiB limit");
    makeCurrent();
    drainGlErrors();
    GlBuffer b;
    std::vector<std::byte> zeros;
    if (data.empty()) zeros.assign(desc.size, std::byte{0});
    const void* initial = data.empty() ? static_cast<const void*>(zeros.data()) : data.data();
    glCreateBuffers(1, &b.id);
    glNamedBufferStorage(b.id, GLsizeiptr(desc.size), initial, GL_DYNAMIC_STORAGE_BIT);
    try {
        checkGl(what + ": allocating " + std::to_string(desc.size) + " bytes");
    } catch (...) {
        glDeleteBuffers(1, &b.id);
        throw;
    }
    ownedBuffers_.insert(b.id);
    return buffers_.add(std::move(b));
}

void GlDriverImpl::updateBuffer(NativeId handle, std::uint64_t offset, std::span<const std::byte> data) {
    makeCurrent();
    glNamedBufferSubData(buffers_[handle].id, GLintptr(offset), GLsizeiptr(data.size()), data.data());
}

NativeId GlDriverImpl::createProgram(std::shared_ptr<const ProgramDesc> desc) {
    if (desc->gl.fragment.empty()) throw Error("program " + quotedName(desc->name) + " has no GLSL for the GL backend");
    makeCurrent();
    return programs_.add(compileSlot(std::move(desc), glsl()));
}

NativeId GlDriverImpl::createStandardProgram(ProgramKind kind, ProgramDesc desc) {
    desc.gl.fragment = standardFragment(kind);
    makeCurrent();
    return programs_.add(compileSlot(std::make_shared<const ProgramDesc>(std::move(desc)), glsl()));
}

void GlDriverImpl::notePipeline(const PipelineDesc& desc, ResolvedPipeline& resolved) {
    const std::string what = "pipeline " + quotedName(desc.name);
    PipelineInfo& info = resolved.info;
    if (desc.alphaTest.alphaToCoverage && options_.nativeAlphaToCoverage) {
        info.exact = false;
        info.note += std::string(info.note.empty() ? "" : "; ") +
                     "native GL_SAMPLE_ALPHA_TO_COVERAGE: the coverage pattern is implementation-defined";
    }
    if (!info.exact) log::warn("GL ", what, ": inexact emulation: ", info.note);
    else if (!resolved.failModes.note.empty()) log::debug("GL ", what, ": ", resolved.failModes.note);
}

void GlDriverImpl::destroyTexture(NativeId h) {
    GlTexture& t = textures_[h];
    makeCurrent();
    framebuffers_.forget(t.id);
    if (!t.imported) {
        glDeleteTextures(1, &t.id);
        ownedTextures_.erase(t.id);
    }
    textures_.remove(h);
}

void GlDriverImpl::destroyBuffer(NativeId h) {
    GlBuffer& b = buffers_[h];
    makeCurrent();
    glDeleteBuffers(1, &b.id);
    ownedBuffers_.erase(b.id);
    buffers_.remove(h);
}

void GlDriverImpl::destroyProgram(NativeId h) {
    makeCurrent();
    programs_.remove(h);
}

void GlDriverImpl::destroyQuery(NativeId h) {
    const GlQuery q = queries_[h];
    queries_.remove(h);
    if (q.id) {
        makeCurrent();
        releaseQueryObject(q.id);
    }
}

bool GlDriverImpl::anySamplesPassed(NativeId h) {
    const GlQuery& q = queries_[h];
    makeCurrent();
    GLuint any = 0;
    glGetQueryObjectuiv(q.id, GL_QUERY_RESULT, &any);
    return any != 0;
}

int GlDriverImpl::maxSamplesFor(GLenum internal) {
    auto it = maxSamplesByFormat_.find(internal);
    if (it != maxSamplesByFormat_.end()) return it->second;
    makeCurrent();
    return maxSamplesByFormat_[internal] = maxSamplesOf(GL_TEXTURE_2D_MULTISAMPLE, internal);
}

void GlDriverImpl::upload(GlTexture& t, const TextureData& data) {
    const GlFormat f = glFormat(t.desc.format);
    uploadLevels(t.desc, data, [&](int level, int w, int h, const std::byte* stored) {
        glTextureSubImage2D(t.id, level, 0, 0, w, h, f.pixelFormat, f.storedType, stored);
    });
}

void GlDriverImpl::clearTexture(const GlTexture& t, const glm::vec4& value) {
    const GlFormat f = glFormat(t.desc.format);
    const std::vector<std::byte> texel = encodeTexel(t.desc.format, value);
    glClearTexImage(t.id, 0, f.pixelFormat, f.storedType, texel.data());
}

// GL leaves new storage undefined; the soft backend starts from zero bytes.
void GlDriverImpl::clearToZero(const GlTexture& t) {
    const GlFormat f = glFormat(t.desc.format);
    const int levels = t.desc.samples > 1 ? 1 : t.desc.mipLevels;
    for (int level = 0; level < levels; ++level) glClearTexImage(t.id, level, f.pixelFormat, f.storedType, nullptr);
}

ProgramSlot& GlDriverImpl::internalProgram(std::optional<ProgramSlot>& slot, const char* name,
                                           const std::string& fragment) {
    if (!slot) slot = compileInternal(name, fragment, glsl());
    return *slot;
}

}  // namespace engine::render::gl
