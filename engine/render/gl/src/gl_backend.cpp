// SPDX-License-Identifier: MIT
// The OpenGL 4.5 core backend. Draws execute as they are recorded (GL queues them); every
// piece of fixed-function state a draw depends on is set for that draw, so a host engine
// sharing the context may change state between calls. Validation and error messages follow
// the soft backend (soft_backend.cpp) so both reject the same input with the same words.
#include "engine/render/gl/gl_backend.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <optional>
#include <set>
#include <utility>

#include <epoxy/gl.h>

#include "engine/core/error.hpp"
#include "engine/core/log.hpp"
#include "engine/render/gl/fail_mode_plan.hpp"
#include "engine/render/gl/gl_program.hpp"
#include "engine/render/memory_budget.hpp"
#include "engine/render/resource_pool.hpp"
#include "engine/render/standard_programs.hpp"
#include "engine/render/validation.hpp"
#include "engine/render/vertex.hpp"
#include "gl_shaders.hpp"
#include "gl_texture_limits.hpp"
#include "texel_codec.hpp"

namespace engine::render::gl {
namespace {


std::string hex(unsigned v) {
    char buf[16];
    std::snprintf(buf, sizeof buf, "0x%04x", v);
    return buf;
}


// Drops errors left by a host (or an earlier, already reported failure) before an operation
// whose own errors are checked.
void drainGlErrors() {
    for (int i = 0; i < 64 && glGetError() != GL_NO_ERROR; ++i) {
    }
}

#ifdef NDEBUG
constexpr bool kCheckEveryDraw = false;
#else
constexpr bool kCheckEveryDraw = true;
#endif

void checkGl(const std::string& what) {
    const GLenum error = glGetError();
    if (error == GL_NO_ERROR) return;
    drainGlErrors();
    const char* name = error == GL_OUT_OF_MEMORY      ? "GL_OUT_OF_MEMORY"
                       : error == GL_INVALID_ENUM      ? "GL_INVALID_ENUM"
                       : error == GL_INVALID_VALUE     ? "GL_INVALID_VALUE"
                       : error == GL_INVALID_OPERATION ? "GL_INVALID_OPERATION"
                                                       : "GL error";
    throw Error(what + ": " + name + " (" + hex(error) + ")");
}

// ---- format and state tables ---------------------------------------------------------

struct GlFormat {
    GLenum internal;
    GLenum pixelFormat;  // of client data
    GLenum storedType;   // type of the stored layout we upload (16F: half floats)
    GLenum readType;     // type we read back (normalized: bytes, float formats: floats)
};

GlFormat glFormat(Format f) {
    switch (f) {
        case Format::RGBA8_UNORM: return {GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, GL_UNSIGNED_BYTE};
        case Format::RGBA8_SRGB: return {GL_SRGB8_ALPHA8, GL_RGBA, GL_UNSIGNED_BYTE, GL_UNSIGNED_BYTE};
        case Format::R8_UNORM: return {GL_R8, GL_RED, GL_UNSIGNED_BYTE, GL_UNSIGNED_BYTE};
        case Format::RG8_UNORM: return {GL_RG8, GL_RG, GL_UNSIGNED_BYTE, GL_UNSIGNED_BYTE};
        case Format::RGBA16F: return {GL_RGBA16F, GL_RGBA, GL_HALF_FLOAT, GL_FLOAT};
        case Format::RG16F: return {GL_RG16F, GL_RG, GL_HALF_FLOAT, GL_FLOAT};
        case Format::R16F: return {GL_R16F, GL_RED, GL_HALF_FLOAT, GL_FLOAT};
        case Format::RGBA32F: return {GL_RGBA32F, GL_RGBA, GL_FLOAT, GL_FLOAT};
        case Format::R32F: return {GL_R32F, GL_RED, GL_FLOAT, GL_FLOAT};
        case Format::D32F: return {GL_DEPTH_COMPONENT32F, GL_DEPTH_COMPONENT, GL_FLOAT, GL_FLOAT};
    }
    return {GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, GL_UNSIGNED_BYTE};
}

// GL 4.5 Table 17.2. SRC_ALPHA_SATURATE is (f, f, f, 1) with f = min(As, 1 - Ad): the same
// as BlendFactor::SrcAlphaSat, whose alpha factor is 1 too; GL 4.x accepts it for the
// destination as well, so every factor maps directly.
GLenum glBlendFactor(BlendFactor f) {
    switch (f) {
        case BlendFactor::Zero: return GL_ZERO;
        case BlendFactor::One: return GL_ONE;
        case BlendFactor::SrcColor: return GL_SRC_COLOR;
        case BlendFactor::InvSrcColor: return GL_ONE_MINUS_SRC_COLOR;
        case BlendFactor::SrcAlpha: return GL_SRC_ALPHA;
        case BlendFactor::InvSrcAlpha: return GL_ONE_MINUS_SRC_ALPHA;
        case BlendFactor::DstColor: return GL_DST_COLOR;
        case BlendFactor::InvDstColor: return GL_ONE_MINUS_DST_COLOR;
        case BlendFactor::DstAlpha: return GL_DST_ALPHA;
        case BlendFactor::InvDstAlpha: return GL_ONE_MINUS_DST_ALPHA;
        case BlendFactor::SrcAlphaSat: return GL_SRC_ALPHA_SATURATE;
        case BlendFactor::ConstantColor: return GL_CONSTANT_COLOR;
        case BlendFactor::InvConstantColor: return GL_ONE_MINUS_CONSTANT_COLOR;
        case BlendFactor::ConstantAlpha: return GL_CONSTANT_ALPHA;
        case BlendFactor::InvConstantAlpha: return GL_ONE_MINUS_CONSTANT_ALPHA;
    }
    return GL_ONE;
}

GLenum glBlendOp(BlendOp op) {
    switch (op) {
        case BlendOp::Add: return GL_FUNC_ADD;
        case BlendOp::Subtract: return GL_FUNC_SUBTRACT;
        case BlendOp::RevSubtract: return GL_FUNC_REVERSE_SUBTRACT;
        case BlendOp::Min: return GL_MIN;
        case BlendOp::Max: return GL_MAX;
    }
    return GL_FUNC_ADD;
}

GLenum glCompare(CompareFunc f) {
    switch (f) {
        case CompareFunc::Never: return GL_NEVER;
        case CompareFunc::Less: return GL_LESS;
        case CompareFunc::Equal: return GL_EQUAL;
        case CompareFunc::LessEqual: return GL_LEQUAL;
        case CompareFunc::Greater: return GL_GREATER;
        case CompareFunc::NotEqual: return GL_NOTEQUAL;
        case CompareFunc::GreaterEqual: return GL_GEQUAL;
        case CompareFunc::Always: return GL_ALWAYS;
    }
    return GL_ALWAYS;
}

GLenum glWrap(AddressMode m) {
    switch (m) {
        case AddressMode::Wrap: return GL_REPEAT;
        case AddressMode::Clamp: return GL_CLAMP_TO_EDGE;
        case AddressMode::Mirror: return GL_MIRRORED_REPEAT;
    }
    return GL_REPEAT;
}

bool readsDstAlpha(BlendFactor f) {
    return f == BlendFactor::DstAlpha || f == BlendFactor::InvDstAlpha || f == BlendFactor::SrcAlphaSat;
}

// Blending whose RGB result depends on the destination alpha (FailModeInputs::rgbReadsDstAlpha).
bool rgbReadsDstAlpha(const BlendState& b) {
    if (b.isPlainWrite() || !(b.writeMask & WriteRGB)) return false;
    if (b.opRgb == BlendOp::Min || b.opRgb == BlendOp::Max) return false;
    return readsDstAlpha(b.srcRgb) || readsDstAlpha(b.dstRgb);
}

// ---- resources -------------------------------------------------------------------------

struct GlTexture {
    TextureDesc desc;
    GLuint id = 0;
    int actualSamples = 1;  // what GL allocated (llvmpipe makes 2x into 4x)
    bool imported = false;
};

struct GlBuffer {
    BufferDesc desc;
    GLuint id = 0;
    std::vector<std::byte> shadow;  // index buffers: read only when a draw may index past its vertices
    std::uint32_t maxIndex = 0;     // index buffers: the largest index (validation's fast accept)
};

// A ProgramDesc compiled: the GL program and the locations of its layout's uniforms.
struct ProgramSlot {
    GlProgram program;
    std::shared_ptr<const ProgramDesc> desc;  // null for the backend's internal programs
    std::vector<GLint> uniforms;              // one per desc->gl.uniforms
    struct TextureUniforms {
        GLint present = -1, filter = -1, premultiplied = -1;
    };
    std::vector<TextureUniforms> textures;  // one per desc->gl.textures
    // The shared fragment tail's (finish()).
    GLint alphaSelect = -1, scissor = -1, alphaFunc = -1, alphaRef = -1, a2cSamples = -1, a2cActual = -1;
};

struct GlPipeline {
    PipelineDesc desc;
    PipelineInfo info;
    std::shared_ptr<const ProgramSlot> program;  // alive while the pipeline is
};

struct PendingTiming {
    std::string pass;
    GLuint query = 0;
    GLuint condition = 0;  // the pass's drawOnlyIfSamplesIn query object, read for `skipped`
};

// An occlusion query handle's GL query object (GL_ANY_SAMPLES_PASSED), made at the first
// pass that counts into it.
struct GlQuery {
    std::string name;
    GLuint id = 0;
    bool counted = false;
};

void KHRONOS_APIENTRY onDebugMessage(GLenum, GLenum type, GLuint id, GLenum severity, GLsizei, const GLchar* message,
                                     const void*) {
    if (severity == GL_DEBUG_SEVERITY_NOTIFICATION) return;
    if (type == GL_DEBUG_TYPE_ERROR) log::warn("GL debug (id ", id, "): ", message);
    else log::debug("GL debug (id ", id, "): ", message);
}

class GlBackendImpl final : public GlBackend {
public:
    GlBackendImpl(const GlOptions& options, std::shared_ptr<GlContext> context)
        : options_(options), context_(std::move(context)), textures_("texture"), buffers_("buffer"),
          pipelines_("pipeline"), queries_("occlusion query"), programs_("program"),
          lookup_{[this](TextureHandle h) -> const TextureDesc& { return textures_.get(h).desc; },
                  [this](BufferHandle h) -> const BufferDesc& { return buffers_.get(h).desc; },
                  [this](BufferHandle h) { return std::span<const std::byte>(buffers_.get(h).shadow); },
                  [this](BufferHandle h) { return buffers_.get(h).maxIndex; },
                  [this](PipelineHandle h) -> const PipelineDesc& { return pipelines_.get(h).desc; },
                  [this](PipelineHandle h) -> const ProgramDesc& { return *pipelines_.get(h).program->desc; }} {
        makeCurrent();
        const char* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
        if (!version) throw Error("GL backend: no GL context is current on this thread");
        GLint major = 0, minor = 0;
        glGetIntegerv(GL_MAJOR_VERSION, &major);
        glGetIntegerv(GL_MINOR_VERSION, &minor);
        GLint profile = 0;
        glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &profile);
        if (major < 4 || (major == 4 && minor < 3))
            throw Error(std::string("GL backend: OpenGL 4.3 or newer needed, the context is ") + version);
        if (major == 4 && minor < 5) {
            for (const char* ext : {"GL_ARB_clip_control", "GL_ARB_direct_state_access", "GL_ARB_buffer_storage",
                                    "GL_ARB_clear_texture"})
                if (!epoxy_has_gl_extension(ext))
                    throw Error(std::string("GL backend: OpenGL ") + version + " lacks " + ext + " (needed below 4.5)");
        }
        glMajor_ = major, glMinor_ = minor;
        info_.vendor = reinterpret_cast<const char*>(glGetString(GL_VENDOR));
        info_.renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
        info_.version = version;
        info_.glslVersion = reinterpret_cast<const char*>(glGetString(GL_SHADING_LANGUAGE_VERSION));
        info_.context = context_ ? context_->describe() : std::string("current context");
        glGetIntegerv(GL_MAX_SAMPLES, &info_.maxSamples);
        textureLimits_ = queryGlTextureLimits(info_.renderer);

        if (options_.debugOutput && (major > 4 || minor >= 3 || epoxy_has_gl_extension("GL_KHR_debug"))) {
            glEnable(GL_DEBUG_OUTPUT);
            glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
            glDebugMessageCallback(onDebugMessage, nullptr);
        }

        drainGlErrors();
        glCreateVertexArrays(1, &emptyVao_);  // full-screen and internal draws: no vertex input
        glCreateVertexArrays(1, &vao_);
        // Attributes: Vertex (binding 0, per vertex) and Instance (binding 1, per instance).
        auto attribute = [&](GLuint location, GLuint binding, GLint size, GLuint offset) {
            glEnableVertexArrayAttrib(vao_, location);
            glVertexArrayAttribFormat(vao_, location, size, GL_FLOAT, GL_FALSE, offset);
            glVertexArrayAttribBinding(vao_, location, binding);
        };
        attribute(0, 0, 3, offsetof(Vertex, position));
        attribute(1, 0, 3, offsetof(Vertex, normal));
        attribute(2, 0, 2, offsetof(Vertex, uv));
        attribute(3, 0, 4, offsetof(Vertex, color));
        for (GLuint c = 0; c < 4; ++c) attribute(4 + c, 1, 4, GLuint(offsetof(Instance, model) + c * sizeof(glm::vec4)));
        attribute(8, 1, 4, offsetof(Instance, tint));
        glVertexArrayBindingDivisor(vao_, 1, 1);
        const Instance identity{};
        glCreateBuffers(1, &identityInstance_);
        glNamedBufferStorage(identityInstance_, sizeof identity, &identity, 0);
        checkGl("GL backend: creating the vertex layout");
        log::debug("GL backend: ", info_.renderer, ", ", info_.version, " (", info_.context, ")");
    }

    ~GlBackendImpl() override {
        try {
            makeCurrent();
        } catch (const Error& e) {
            log::warn("GL backend: cannot make the context current to release objects: ", e.what());
            return;
        }
        for (const auto& [key, fbo] : framebuffers_) glDeleteFramebuffers(1, &fbo);
        for (GLuint t : ownedTextures_) glDeleteTextures(1, &t);
        for (GLuint b : ownedBuffers_) glDeleteBuffers(1, &b);
        for (GLuint s : samplers_)
            if (s) glDeleteSamplers(1, &s);
        for (const PendingTiming& p : pendingTimings_) glDeleteQueries(1, &p.query);
        if (passQuery_) glDeleteQueries(1, &passQuery_);
        for (GLuint q : occlusionQueries_) glDeleteQueries(1, &q);
        glDeleteBuffers(1, &identityInstance_);
        glDeleteVertexArrays(1, &vao_);
        glDeleteVertexArrays(1, &emptyVao_);
        // GL program objects are deleted while the context is current.
        pipelines_ = ResourcePool<PipelineTag, GlPipeline>("pipeline");
        programs_ = ResourcePool<ProgramTag, std::shared_ptr<const ProgramSlot>>("program");
        for (auto& p : standardPrograms_) p.reset();
        resolveColor_.reset();
        resolveDepth_.reset();
        nothing_.reset();
    }

    std::string name() const override { return "gl"; }
    const GlInfo& info() const override { return info_; }
    GlContext* context() const override { return context_.get(); }

    // ---- resources ---------------------------------------------------------------------

    TextureHandle createTexture(const TextureDesc& desc, const TextureData* data) override {
        const std::string what = "texture " + quotedName(desc.name);
        validateTexture(desc, what);
        const GlFormat f = glFormat(desc.format);
        if (desc.samples > 1) {
            const int supported = maxSamplesFor(f.internal);
            if (desc.samples > supported)
                throw Error(what + ": " + std::to_string(desc.samples) + " samples exceed this GL implementation's " +
                            std::to_string(supported) + " for " + std::string(formatName(desc.format)) + " (" +
                            info_.renderer + ")");
            if (data && !data->levels.empty())
                throw Error(what + ": initial data for a multisampled texture (the GL backend cannot upload samples)");
        }
        makeCurrent();
        checkGlTextureFits(desc, what, textureLimits_);
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
            if (data && !data->levels.empty()) upload(t, *data, what);
            else clearToZero(t);
            checkGl(what + ": initialising");
        } catch (...) {
            glDeleteTextures(1, &t.id);
            throw;
        }
        ownedTextures_.insert(t.id);
        return textures_.add(std::move(t));
    }

    TextureHandle importTexture(unsigned int id, const TextureDesc& desc) override {
        const std::string what = "imported texture " + quotedName(desc.name);
        validateTexture(desc, what);
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
            throw Error(what + ": GL texture is " + std::to_string(width) + "x" + std::to_string(height) + ", described as " +
                        std::to_string(desc.width) + "x" + std::to_string(desc.height));
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

    unsigned int glTexture(TextureHandle h) const override { return textures_.get(h).id; }

    BufferHandle createBuffer(const BufferDesc& desc, std::span<const std::byte> data) override {
        const std::string what = "buffer " + quotedName(desc.name);
        validateBuffer(desc, data, what);
        if (desc.size > (std::uint64_t(1) << 32))
            throw Error(what + ": " + std::to_string(desc.size >> 20) + " MiB exceeds the GL backend's 4 GiB limit");
        makeCurrent();
        drainGlErrors();
        GlBuffer b;
        b.desc = desc;
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
        if (desc.kind == BufferKind::Index) {
            const auto* p = static_cast<const std::byte*>(initial);
            b.shadow.assign(p, p + desc.size);
            b.maxIndex = largestIndex(b.shadow);
        }
        ownedBuffers_.insert(b.id);
        return buffers_.add(std::move(b));
    }

    void updateBuffer(BufferHandle handle, std::uint64_t offset, std::span<const std::byte> data) override {
        GlBuffer& b = buffers_.get(handle);
        if (offset > b.desc.size || data.size() > b.desc.size - offset)
            throw Error("buffer " + quotedName(b.desc.name) + ": update of " + std::to_string(data.size()) +
                        " bytes at offset " + std::to_string(offset) + " overruns its " + std::to_string(b.desc.size) +
                        " bytes");
        if (data.empty()) return;
        makeCurrent();
        glNamedBufferSubData(b.id, GLintptr(offset), GLsizeiptr(data.size()), data.data());
        if (!b.shadow.empty()) {
            std::memcpy(b.shadow.data() + offset, data.data(), data.size());
            b.maxIndex = largestIndex(b.shadow);
        }
    }

    ProgramHandle createProgram(const ProgramDesc& desc) override {
        if (desc.gl.fragment.empty()) throw Error("program " + quotedName(desc.name) + " has no GLSL for the GL backend");
        makeCurrent();
        return programs_.add(compile(std::make_shared<const ProgramDesc>(desc)));
    }

    PipelineHandle createPipeline(const PipelineDesc& desc) override {
        const std::string what = "pipeline " + quotedName(desc.name);
        if (desc.alphaTest.enabled && !std::isfinite(desc.alphaTest.reference))
            throw Error(what + ": alpha reference is not finite");
        std::shared_ptr<const ProgramSlot> program = programFor(desc.program);
        if (program->desc->vertexInput == VertexInput::Fullscreen && desc.depth.test)
            throw Error(what + ": full-screen program " + program->desc->name + " cannot depth-test");
        GlPipeline p{desc, {}, std::move(program)};
        bool anyRgb = false, anyAlpha = false, plain = true, readsDstAlpha = false;
        for (const BlendState& b : desc.blend) {
            anyRgb = anyRgb || (b.writeMask & WriteRGB);
            anyAlpha = anyAlpha || (b.writeMask & WriteA);
            plain = plain && b.isPlainWrite();
            readsDstAlpha = readsDstAlpha || rgbReadsDstAlpha(b);
        }
        const FailModePlan plan = planFailMode({desc.alphaTest, desc.depth.test, desc.depth.write, desc.depth.func,
                                                anyRgb, anyAlpha, readsDstAlpha,
                                                options_.failModes == FailModeStrategy::PerTriangle});
        p.info.alphaTestDropped = plan.alphaTestDropped;
        p.info.blendIsPlainWrite = plain;
        p.info.exact = plan.exact;
        if (!plan.exact) p.info.note = plan.note;
        if (desc.alphaTest.alphaToCoverage && options_.nativeAlphaToCoverage) {
            p.info.exact = false;
            p.info.note += std::string(p.info.note.empty() ? "" : "; ") +
                           "native GL_SAMPLE_ALPHA_TO_COVERAGE: the coverage pattern is implementation-defined";
        }
        if (!p.info.exact) log::warn("GL ", what, ": inexact emulation: ", p.info.note);
        else if (!plan.note.empty()) log::debug("GL ", what, ": ", plan.note);
        return pipelines_.add(std::move(p));
    }

    void destroy(TextureHandle h) override {
        GlTexture& t = textures_.get(h);
        makeCurrent();
        forgetFramebuffersOf(t.id);
        if (!t.imported) {
            glDeleteTextures(1, &t.id);
            ownedTextures_.erase(t.id);
        }
        textures_.remove(h);
    }

    void destroy(BufferHandle h) override {
        GlBuffer& b = buffers_.get(h);
        makeCurrent();
        glDeleteBuffers(1, &b.id);
        ownedBuffers_.erase(b.id);
        buffers_.remove(h);
    }

    void destroy(ProgramHandle h) override {
        makeCurrent();
        programs_.remove(h);
    }
    void destroy(PipelineHandle h) override { pipelines_.remove(h); }

    QueryHandle createQuery(const std::string& name) override { return queries_.add({name}); }

    void destroy(QueryHandle h) override {
        const GlQuery q = queries_.get(h);
        checkQueryUse(h, q.name, pass_ ? &*pass_ : nullptr, true);
        queries_.remove(h);
        if (q.id) {
            makeCurrent();
            releaseQueryObject(q.id);
        }
    }

    bool anySamplesPassed(QueryHandle h) override {
        const GlQuery& q = queries_.get(h);
        checkQueryUse(h, q.name, pass_ ? &*pass_ : nullptr, false);
        if (!q.counted) throw uncountedQueryError(q.name);
        makeCurrent();
        GLuint any = 0;
        glGetQueryObjectuiv(q.id, GL_QUERY_RESULT, &any);
        return any != 0;
    }

    const TextureDesc& describe(TextureHandle h) const override { return textures_.get(h).desc; }
    PipelineInfo pipelineInfo(PipelineHandle h) const override { return pipelines_.get(h).info; }

    // ---- passes ------------------------------------------------------------------------

    void beginPass(const PassDesc& pass) override {
        if (pass_) throw Error("pass " + quotedName(pass.name) + " begun while pass " + quotedName(pass_->name) + " is open");
        const PassExtent extent = validatePass(pass, lookup_);
        if (pass.countSamplesInto) queries_.get(pass.countSamplesInto);  // alive, or a clear error now
        if (pass.drawOnlyIfSamplesIn && !queries_.get(pass.drawOnlyIfSamplesIn).counted)
            throw uncountedQueryError(queries_.get(pass.drawOnlyIfSamplesIn).name);
        const int width = extent.width, height = extent.height, samples = extent.samples;
        int actual = 1;  // the samples the driver really gave (llvmpipe: 4 for 2)
        std::vector<GLuint> colorIds;
        targets_.clear();
        for (const ColorAttachment& c : pass.color) {
            if (!c.texture) continue;
            const GlTexture& t = textures_.get(c.texture);
            actual = t.actualSamples;
            colorIds.push_back(t.id);
            targets_.push_back({c.texture, t.desc.format, c});
        }
        GLuint depthId = 0;
        if (pass.depth.texture) {
            const GlTexture& t = textures_.get(pass.depth.texture);
            actual = t.actualSamples;
            depthId = t.id;
        }

        makeCurrent();
        drainGlErrors();
        const GLuint fbo = framebufferFor(colorIds, depthId, "pass " + quotedName(pass.name));

        // The pass's framebuffer is bound, and made known to the driver by a draw that
        // rasterizes nothing, before the query begins: llvmpipe starts the clock of a
        // TIME_ELAPSED query in the tiles of the current framebuffer, and before the first
        // draw into one there are none (the query would report the time since boot).
        applyBaseState();
        glBindFramebuffer(GL_FRAMEBUFFER, fbo);
        glViewport(0, 0, width, height);
        validateFramebufferState();
        glCreateQueries(GL_TIME_ELAPSED, 1, &passQuery_);
        glBeginQuery(GL_TIME_ELAPSED, passQuery_);
        try {
            checkGl("pass " + quotedName(pass.name) + ": starting its timer query");
        } catch (...) {
            glDeleteQueries(1, &passQuery_);
            passQuery_ = 0;
            throw;
        }

        // Clears store the soft backend's bits: the value is encoded here (UNORM rounding,
        // sRGB curve, half rounding to nearest even, depth unclamped) and written with
        // glClearTexImage, which converts nothing; GL's own clear conversion rounds ties to
        // even and halves toward zero on llvmpipe.
        for (const Target& target : targets_)
            if (target.attachment.load == LoadOp::Clear)
                clearTexture(textures_.get(target.texture), target.attachment.clear);
        if (pass.depth.texture && pass.depth.load == LoadOp::Clear)
            clearTexture(textures_.get(pass.depth.texture), glm::vec4(pass.depth.clear));
        try {
            checkGl("pass " + quotedName(pass.name) + ": clearing");
        } catch (...) {
            glEndQuery(GL_TIME_ELAPSED);
            glDeleteQueries(1, &passQuery_);
            passQuery_ = 0;
            throw;
        }
        // Queries begin after the clears (glClearTexImage passes no samples and is not
        // conditional anyway): only the pass's draws are counted, or skipped.
        if (pass.countSamplesInto) {
            GlQuery& q = queries_.get(pass.countSamplesInto);
            // A pending timing still has to read the object's last result: count into a new one.
            if (q.id && conditionPending(q.id)) {
                retiredQueries_.push_back(q.id);
                q.id = 0;
            }
            if (!q.id) {
                glCreateQueries(GL_ANY_SAMPLES_PASSED, 1, &q.id);
                occlusionQueries_.insert(q.id);
            }
            glBeginQuery(GL_ANY_SAMPLES_PASSED, q.id);
        }
        passCondition_ = 0;
        if (pass.drawOnlyIfSamplesIn) {
            passCondition_ = queries_.get(pass.drawOnlyIfSamplesIn).id;
            glBeginConditionalRender(passCondition_, GL_QUERY_WAIT);
        }
        pass_ = pass;
        passWidth_ = width, passHeight_ = height, passSamples_ = samples, passActualSamples_ = actual;
        passFbo_ = fbo;
    }

    void draw(const DrawDesc& d) override {
        if (!pass_) throw Error("draw outside a pass");
        validateDraw(d, *pass_, {passWidth_, passHeight_, passSamples_}, lookup_);
        makeCurrent();
        execute(d);
    }

    void endPass() override {
        if (!pass_) throw Error("endPass without beginPass");
        makeCurrent();
        if (passCondition_) glEndConditionalRender();
        if (pass_->countSamplesInto) {
            glEndQuery(GL_ANY_SAMPLES_PASSED);
            queries_.get(pass_->countSamplesInto).counted = true;
        }
        glEndQuery(GL_TIME_ELAPSED);
        pendingTimings_.push_back({pass_->name, std::exchange(passQuery_, 0u), std::exchange(passCondition_, 0u)});
        pass_.reset();
        targets_.clear();
        checkGl("pass: ending");
    }

    void abortPass() noexcept override {
        if (!pass_) return;
        try {
            makeCurrent();
            if (passCondition_) glEndConditionalRender();
            if (pass_->countSamplesInto) {
                glEndQuery(GL_ANY_SAMPLES_PASSED);
                queries_.get(pass_->countSamplesInto).counted = false;
            }
            glEndQuery(GL_TIME_ELAPSED);
            glDeleteQueries(1, &passQuery_);
        } catch (...) {  // no current context or a destroyed query: the pass is dropped all the same
        }
        passQuery_ = passCondition_ = 0;
        pass_.reset();
        targets_.clear();
    }

    void resolve(const ResolveDesc& r) override {
        GlTexture& src = textures_.get(r.source);
        GlTexture& dst = textures_.get(r.destination);
        if (src.desc.width != dst.desc.width || src.desc.height != dst.desc.height || src.desc.format != dst.desc.format ||
            dst.desc.samples != 1)
            throw Error("resolve " + quotedName(src.desc.name) + " -> " + quotedName(dst.desc.name) +
                        ": needs the same size and format and a single-sampled destination");
        const std::string what = "resolve " + quotedName(src.desc.name) + " -> " + quotedName(dst.desc.name);
        makeCurrent();
        drainGlErrors();
        const bool depth = formatInfo(src.desc.format).isDepth;
        if (src.actualSamples == 1) {
            glCopyImageSubData(src.id, GL_TEXTURE_2D, 0, 0, 0, 0, dst.id, GL_TEXTURE_2D, 0, 0, 0, 0, src.desc.width,
                               src.desc.height, 1);
            checkGl(what);
            return;
        }
        ProgramSlot& program = depth ? internalProgram(resolveDepth_, "resolve depth", resolveDepthFragmentSource())
                                     : internalProgram(resolveColor_, "resolve colour", resolveColorFragmentSource());
        GLuint fbo = 0;
        glCreateFramebuffers(1, &fbo);
        if (depth) {
            glNamedFramebufferTexture(fbo, GL_DEPTH_ATTACHMENT, dst.id, 0);
            glNamedFramebufferDrawBuffer(fbo, GL_NONE);
        } else {
            glNamedFramebufferTexture(fbo, GL_COLOR_ATTACHMENT0, dst.id, 0);
            glNamedFramebufferDrawBuffer(fbo, GL_COLOR_ATTACHMENT0);
        }
        glNamedFramebufferReadBuffer(fbo, GL_NONE);
        try {
            checkFramebuffer(fbo, what);
        } catch (...) {
            glDeleteFramebuffers(1, &fbo);
            throw;
        }
        applyBaseState();
        glBindFramebuffer(GL_FRAMEBUFFER, fbo);
        glViewport(0, 0, dst.desc.width, dst.desc.height);
        glDisable(GL_SCISSOR_TEST);
        glDisable(GL_CULL_FACE);
        glDisable(GL_SAMPLE_ALPHA_TO_COVERAGE);
        glDisablei(GL_BLEND, 0);
        glColorMaski(0, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        if (depth) {
            glEnable(GL_DEPTH_TEST);
            glDepthFunc(GL_ALWAYS);
            glDepthMask(GL_TRUE);
        } else {
            glDisable(GL_DEPTH_TEST);
            glDepthMask(GL_FALSE);
        }
        glUseProgram(program.program.id());
        glProgramUniform1i(program.program.id(), program.program.uniform("u_samples"), src.actualSamples);
        if (depth)
            glProgramUniform1i(program.program.id(), program.program.uniform("u_greater"),
                               isCloser(r.depthFunc, 1.0f, 0.0f) ? 1 : 0);
        glBindTextureUnit(0, src.id);
        glBindSampler(0, 0);
        glBindVertexArray(emptyVao_);
        glDrawArrays(GL_TRIANGLES, 0, 3);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glDeleteFramebuffers(1, &fbo);
        checkGl(what);
    }

    Readback readback(TextureHandle h) override {
        const GlTexture& t = textures_.get(h);
        if (t.desc.samples != 1) throw Error("readback of " + quotedName(t.desc.name) + ": multisampled; resolve it first");
        const FormatInfo& info = formatInfo(t.desc.format);
        const GlFormat f = glFormat(t.desc.format);
        Readback r;
        r.width = t.desc.width;
        r.height = t.desc.height;
        r.channels = info.channels;
        r.format = t.desc.format;
        const std::size_t values = std::size_t(r.width) * r.height * r.channels;
        checkFitsInMemory(values * sizeof(float), "readback of " + quotedName(t.desc.name) + " as float", hostMemoryAvailable);
        r.values.resize(values);
        makeCurrent();
        drainGlErrors();
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glPixelStorei(GL_PACK_ROW_LENGTH, 0);
        glPixelStorei(GL_PACK_SKIP_ROWS, 0);
        glPixelStorei(GL_PACK_SKIP_PIXELS, 0);
        glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
        const std::string what = "readback of " + quotedName(t.desc.name);
        if (info.isNormalized()) {
            // Stored codes / 255; sRGB is not decoded (a texture view as RGBA8 reads the codes).
            std::vector<std::uint8_t> bytes(values);
            GLuint source = t.id, view = 0;
            if (info.isSrgb) {
                glGenTextures(1, &view);
                glTextureView(view, GL_TEXTURE_2D, t.id, GL_RGBA8, 0, 1, 0, 1);
                checkGl(what + ": viewing the sRGB texture as RGBA8");
                source = view;
            }
            glGetTextureImage(source, 0, f.pixelFormat, GL_UNSIGNED_BYTE, GLsizei(bytes.size()), bytes.data());
            if (view) glDeleteTextures(1, &view);
            checkGl(what);
            for (std::size_t i = 0; i < values; ++i) r.values[i] = float(bytes[i]) / 255.0f;
        } else {
            glGetTextureImage(t.id, 0, f.pixelFormat, GL_FLOAT, GLsizei(values * sizeof(float)), r.values.data());
            checkGl(what);
        }
        return r;
    }

    std::vector<PassTiming> takeTimings() override {
        std::vector<PassTiming> out;
        if (pendingTimings_.empty()) return out;
        makeCurrent();
        for (const PendingTiming& p : pendingTimings_) {
            GLuint64 ns = 0;
            glGetQueryObjectui64v(p.query, GL_QUERY_RESULT, &ns);
            glDeleteQueries(1, &p.query);
            GLuint any = 1;
            if (p.condition) glGetQueryObjectuiv(p.condition, GL_QUERY_RESULT, &any);
            out.push_back({p.pass, double(ns) / 1.0e6, any == 0});
        }
        pendingTimings_.clear();
        for (GLuint q : std::exchange(retiredQueries_, {})) releaseQueryObject(q);
        return out;
    }

    bool present(TextureHandle h) override {
        const GlTexture& t = textures_.get(h);
        if (t.desc.samples != 1) throw Error("present of " + quotedName(t.desc.name) + ": multisampled; resolve it first");
        if (formatInfo(t.desc.format).isDepth) throw Error("present of " + quotedName(t.desc.name) + ": a depth texture");
        if (pass_) throw Error("present of " + quotedName(t.desc.name) + " while pass " + quotedName(pass_->name) + " is open");
        if (!context_ || !context_->hasWindow()) return false;
        const glm::ivec2 size = context_->framebufferSize();
        if (size.x <= 0 || size.y <= 0) return false;  // minimised: nothing to show, nothing to swap
        makeCurrent();
        drainGlErrors();
        GLuint fbo = 0;
        glCreateFramebuffers(1, &fbo);
        glNamedFramebufferTexture(fbo, GL_COLOR_ATTACHMENT0, t.id, 0);
        glNamedFramebufferReadBuffer(fbo, GL_COLOR_ATTACHMENT0);
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
        // Stored codes are copied as they are (sRGB textures hold display-encoded values).
        glDisable(GL_FRAMEBUFFER_SRGB);
        glDisable(GL_SCISSOR_TEST);
        glColorMaski(0, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        const bool same = size.x == t.desc.width && size.y == t.desc.height;
        // Row 0 at the top of the window: the default framebuffer's row 0 is its bottom.
        glBlitNamedFramebuffer(fbo, 0, 0, 0, t.desc.width, t.desc.height, 0, size.y, size.x, 0, GL_COLOR_BUFFER_BIT,
                               same ? GL_NEAREST : GL_LINEAR);
        glDeleteFramebuffers(1, &fbo);
        glEnable(GL_FRAMEBUFFER_SRGB);
        checkGl("present of " + quotedName(t.desc.name));
        context_->swapBuffers();
        return true;
    }

private:
    struct Target {
        TextureHandle texture;
        Format format;
        ColorAttachment attachment;
    };

    void makeCurrent() {
        if (context_) context_->makeCurrent();
    }

    int maxSamplesFor(GLenum internal) {
        auto it = maxSamplesByFormat_.find(internal);
        if (it != maxSamplesByFormat_.end()) return it->second;
        makeCurrent();
        GLint count = 0;
        glGetInternalformativ(GL_TEXTURE_2D_MULTISAMPLE, internal, GL_NUM_SAMPLE_COUNTS, 1, &count);
        std::vector<GLint> counts(std::size_t(std::max(count, 0)));
        if (count > 0) glGetInternalformativ(GL_TEXTURE_2D_MULTISAMPLE, internal, GL_SAMPLES, count, counts.data());
        int best = 1;
        for (GLint c : counts) best = std::max(best, int(c));
        return maxSamplesByFormat_[internal] = best;
    }

    void upload(GlTexture& t, const TextureData& data, const std::string& what) {
        const TextureDesc& desc = t.desc;
        if (data.levels.size() > std::size_t(desc.mipLevels))
            throw Error(what + ": " + std::to_string(data.levels.size()) + " levels of data for " +
                        std::to_string(desc.mipLevels) + " mip levels");
        const bool half = desc.format == Format::RGBA16F || desc.format == Format::RG16F || desc.format == Format::R16F;
        const int channels = formatInfo(desc.format).channels;
        const GlFormat f = glFormat(desc.format);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
        glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
        glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
        glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
        std::vector<std::byte> previous;
        int previousWidth = 0, previousHeight = 0;
        for (int level = 0; level < desc.mipLevels; ++level) {
            const int w = std::max(1, desc.width >> level), h = std::max(1, desc.height >> level);
            const std::size_t pixels = std::size_t(w) * h;
            std::vector<std::byte> stored;
            if (std::size_t(level) < data.levels.size()) {
                const std::size_t expected =
                    half ? pixels * channels * sizeof(float) : pixels * std::size_t(formatInfo(desc.format).bytesPerPixel);
                if (data.levels[level].size() != expected)
                    throw Error(what + ": level " + std::to_string(level) + " has " +
                                std::to_string(data.levels[level].size()) + " bytes, expected " + std::to_string(expected));
                stored = toStored(desc.format, data.levels[level], pixels);
            } else {
                stored = generateMip(desc.format, previous, previousWidth, previousHeight, w, h);
            }
            glTextureSubImage2D(t.id, level, 0, 0, w, h, f.pixelFormat, f.storedType, stored.data());
            previous = std::move(stored);
            previousWidth = w, previousHeight = h;
        }
    }

    void validateFramebufferState() {
        ProgramSlot& nothing = internalProgram(nothing_, "validate", "#version 450 core\nvoid main() {}\n");
        glUseProgram(nothing.program.id());
        glBindVertexArray(emptyVao_);
        glEnable(GL_RASTERIZER_DISCARD);
        glDrawArrays(GL_TRIANGLES, 0, 3);
        glDisable(GL_RASTERIZER_DISCARD);
    }

    void clearTexture(const GlTexture& t, const glm::vec4& value) {
        const GlFormat f = glFormat(t.desc.format);
        const std::vector<std::byte> texel = encodeTexel(t.desc.format, value);
        glClearTexImage(t.id, 0, f.pixelFormat, f.storedType, texel.data());
    }

    // GL leaves new storage undefined; the soft backend starts from zero bytes.
    void clearToZero(const GlTexture& t) {
        const GlFormat f = glFormat(t.desc.format);
        const int levels = t.desc.samples > 1 ? 1 : t.desc.mipLevels;
        for (int level = 0; level < levels; ++level) glClearTexImage(t.id, level, f.pixelFormat, f.storedType, nullptr);
    }

    GLuint framebufferFor(const std::vector<GLuint>& colors, GLuint depth, const std::string& what) {
        std::vector<GLuint> key = colors;
        key.push_back(0);
        key.push_back(depth);
        auto it = framebuffers_.find(key);
        if (it != framebuffers_.end()) return it->second;
        GLuint fbo = 0;
        glCreateFramebuffers(1, &fbo);
        std::vector<GLenum> drawBuffers;
        for (std::size_t i = 0; i < colors.size(); ++i) {
            glNamedFramebufferTexture(fbo, GLenum(GL_COLOR_ATTACHMENT0 + i), colors[i], 0);
            drawBuffers.push_back(GLenum(GL_COLOR_ATTACHMENT0 + i));
        }
        if (depth) glNamedFramebufferTexture(fbo, GL_DEPTH_ATTACHMENT, depth, 0);
        if (drawBuffers.empty()) glNamedFramebufferDrawBuffer(fbo, GL_NONE);
        else glNamedFramebufferDrawBuffers(fbo, GLsizei(drawBuffers.size()), drawBuffers.data());
        glNamedFramebufferReadBuffer(fbo, GL_NONE);
        try {
            checkFramebuffer(fbo, what);
        } catch (...) {
            glDeleteFramebuffers(1, &fbo);
            throw;
        }
        framebuffers_.emplace(std::move(key), fbo);
        return fbo;
    }

    bool conditionPending(GLuint query) const {
        return std::any_of(pendingTimings_.begin(), pendingTimings_.end(),
                           [&](const PendingTiming& p) { return p.condition == query; });
    }

    // Deleted now, or once the pending timing that reads it is taken.
    void releaseQueryObject(GLuint query) {
        if (conditionPending(query)) {
            retiredQueries_.push_back(query);
            return;
        }
        glDeleteQueries(1, &query);
        occlusionQueries_.erase(query);
    }

    void forgetFramebuffersOf(GLuint texture) {
        for (auto it = framebuffers_.begin(); it != framebuffers_.end();) {
            if (std::find(it->first.begin(), it->first.end(), texture) != it->first.end()) {
                glDeleteFramebuffers(1, &it->second);
                it = framebuffers_.erase(it);
            } else {
                ++it;
            }
        }
    }

    // State every pass, resolve and draw relies on; set again each time because a host
    // sharing the context may have changed it.
    void applyBaseState() {
        glClipControl(GL_UPPER_LEFT, GL_ZERO_TO_ONE);
        glDepthRange(0.0, 1.0);
        glEnable(GL_FRAMEBUFFER_SRGB);
        glEnable(GL_MULTISAMPLE);
        glDisable(GL_DITHER);
        glDisable(GL_STENCIL_TEST);
        glDisable(GL_POLYGON_OFFSET_FILL);
        glDisable(GL_RASTERIZER_DISCARD);
        glDisable(GL_COLOR_LOGIC_OP);
        glDisable(GL_DEPTH_CLAMP);
        glDisable(GL_SAMPLE_SHADING);
        glDisable(GL_SAMPLE_COVERAGE);
        glDisable(GL_SAMPLE_MASK);
        glDisable(GL_PRIMITIVE_RESTART);
        glDisable(GL_PRIMITIVE_RESTART_FIXED_INDEX);
        glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
        glClampColor(GL_CLAMP_READ_COLOR, GL_FALSE);
    }

    // ---- programs ------------------------------------------------------------------------

    static void locateTail(ProgramSlot& s) {
        const GlProgram& p = s.program;
        s.alphaSelect = p.uniform("u_alphaSelect");
        s.scissor = p.uniform("u_scissor");
        s.alphaFunc = p.uniform("u_alphaFunc");
        s.alphaRef = p.uniform("u_alphaRef");
        s.a2cSamples = p.uniform("u_a2cSamples");
        s.a2cActual = p.uniform("u_a2cActual");
    }

    std::shared_ptr<const ProgramSlot> compile(std::shared_ptr<const ProgramDesc> desc) {
        auto s = std::make_shared<ProgramSlot>();
        s->program = compileProgram(desc->name, withGlslVersion(vertexSource(desc->vertexInput), glMajor_, glMinor_),
                                    withGlslVersion(fragmentSource(desc->vertexInput, desc->gl.fragment), glMajor_, glMinor_));
        for (const UniformField& u : desc->gl.uniforms) s->uniforms.push_back(s->program.uniform(u.name));
        for (const TextureField& t : desc->gl.textures) {
            ProgramSlot::TextureUniforms& l = s->textures.emplace_back();
            if (t.presentUniform) l.present = s->program.uniform(t.presentUniform);
            if (t.filterUniform) l.filter = s->program.uniform(t.filterUniform);
            if (t.premultipliedUniform) l.premultiplied = s->program.uniform(t.premultipliedUniform);
        }
        locateTail(*s);
        s->desc = std::move(desc);
        return s;
    }

    std::shared_ptr<const ProgramSlot> programFor(const ProgramRef& ref) {
        if (ref.created) return programs_.get(ref.created);
        const auto index = std::size_t(ref.standard);
        if (index >= standardPrograms_.size()) throw Error("unknown standard program " + std::to_string(index));
        std::shared_ptr<const ProgramSlot>& slot = standardPrograms_[index];
        if (!slot) {
            ProgramDesc desc = standardProgramDesc(ref.standard);
            desc.gl.fragment = standardFragment(ref.standard);
            makeCurrent();
            slot = compile(std::make_shared<const ProgramDesc>(std::move(desc)));
        }
        return slot;
    }

    ProgramSlot& internalProgram(std::optional<ProgramSlot>& slot, const char* name, const std::string& fragment) {
        if (!slot) {
            ProgramSlot s;
            s.program = compileProgram(name, withGlslVersion(fullscreenVertexSource(), glMajor_, glMinor_),
                                       withGlslVersion(fragment, glMajor_, glMinor_));
            slot = std::move(s);
        }
        return *slot;
    }

    GLuint sampler(const SamplerState& s) {
        const std::size_t index = std::size_t(s.filter) * 9 + std::size_t(s.addressU) * 3 + std::size_t(s.addressV);
        GLuint& id = samplers_[index];
        if (!id) {
            glCreateSamplers(1, &id);
            // Bilinear reads level 0 only: a non-mipmapped minification filter never leaves the base level.
            const GLenum minFilter = s.filter == Filter::Nearest    ? GL_NEAREST
                                     : s.filter == Filter::Bilinear ? GL_LINEAR
                                                                    : GL_LINEAR_MIPMAP_LINEAR;
            glSamplerParameteri(id, GL_TEXTURE_MIN_FILTER, GLint(minFilter));
            glSamplerParameteri(id, GL_TEXTURE_MAG_FILTER, s.filter == Filter::Nearest ? GL_NEAREST : GL_LINEAR);
            glSamplerParameteri(id, GL_TEXTURE_WRAP_S, GLint(glWrap(s.addressU)));
            glSamplerParameteri(id, GL_TEXTURE_WRAP_T, GLint(glWrap(s.addressV)));
        }
        return id;
    }

    // The draw's parameters as the program's layout lays them out (ProgramDesc::gl).
    void setParams(const ProgramSlot& s, const DrawParams& params) {
        const GLuint p = s.program.id();
        const auto* bytes = static_cast<const std::byte*>(params.data());
        const GlslProgram& gl = s.desc->gl;
        for (std::size_t i = 0; i < gl.uniforms.size(); ++i) setUniform(p, s.uniforms[i], gl.uniforms[i], bytes);
        for (std::size_t i = 0; i < gl.textures.size(); ++i) {
            const TextureField& field = gl.textures[i];
            const ProgramSlot::TextureUniforms& l = s.textures[i];
            const auto unit = GLuint(field.unit);
            if (field.read == TextureRead::Sampled) {
                TextureBinding binding;
                std::memcpy(&binding, bytes + field.offset, sizeof binding);
                if (!binding.texture) {
                    glProgramUniform1i(p, l.present, 0);
                    glBindTextureUnit(unit, 0);
                    continue;
                }
                const GlTexture& t = textures_.get(binding.texture);
                glProgramUniform1i(p, l.present, 1);
                glProgramUniform1i(p, l.filter, int(binding.sampler.filter));
                if (field.premultipliedUniform)
                    glProgramUniform1i(p, l.premultiplied, t.desc.alpha == AlphaMode::Premultiplied ? 1 : 0);
                glBindTextureUnit(unit, t.id);
                glBindSampler(unit, sampler(binding.sampler));
            } else {
                TextureHandle handle;
                std::memcpy(&handle, bytes + field.offset, sizeof handle);
                glBindTextureUnit(unit, handle ? textures_.get(handle).id : 0);
                glBindSampler(unit, 0);
                if (field.presentUniform) glProgramUniform1i(p, l.present, handle ? 1 : 0);
            }
        }
    }

    static void setUniform(GLuint p, GLint location, const UniformField& field, const std::byte* bytes) {
        const std::byte* at = bytes + field.offset;
        auto read = [at](auto& value) { std::memcpy(&value, at, sizeof value); };
        switch (field.type) {
            case UniformType::Float: {
                float v;
                read(v);
                glProgramUniform1f(p, location, v);
                return;
            }
            case UniformType::Int: {
                int v;
                read(v);
                glProgramUniform1i(p, location, v);
                return;
            }
            case UniformType::Bool: {
                bool v;
                read(v);
                glProgramUniform1i(p, location, v ? 1 : 0);
                return;
            }
            case UniformType::Byte: {
                std::uint8_t v;
                read(v);
                glProgramUniform1i(p, location, int(v));
                return;
            }
            case UniformType::Vec2: {
                glm::vec2 v;
                read(v);
                glProgramUniform2fv(p, location, 1, &v[0]);
                return;
            }
            case UniformType::Vec3: {
                glm::vec3 v;
                read(v);
                glProgramUniform3fv(p, location, 1, &v[0]);
                return;
            }
            case UniformType::Direction: {
                glm::vec3 v;
                read(v);
                v = glm::normalize(v);  // as the soft programs normalise it
                glProgramUniform3fv(p, location, 1, &v[0]);
                return;
            }
            case UniformType::Vec4: {
                glm::vec4 v;
                read(v);
                glProgramUniform4fv(p, location, 1, &v[0]);
                return;
            }
            case UniformType::Mat4: {
                glm::mat4 v;
                read(v);
                glProgramUniformMatrix4fv(p, location, 1, GL_FALSE, &v[0][0]);
                return;
            }
        }
    }

    // ---- draws ---------------------------------------------------------------------------

    void execute(const DrawDesc& d) {
        const GlPipeline& pipeline = pipelines_.get(d.pipeline);
        const PipelineDesc& desc = pipeline.desc;
        const ProgramSlot& s = *pipeline.program;
        const bool fullscreen = s.desc->vertexInput == VertexInput::Fullscreen;
        const GLuint p = s.program.id();

        // Effective state, as the soft backend's drawStateFor computes it.
        const bool depthTest = desc.depth.test && pass_->depth.texture;
        const bool depthWrite = depthTest && desc.depth.write;
        std::array<std::uint8_t, kMaxColorTargets> masks{};
        std::array<bool, kMaxColorTargets> blendNeeded{};
        bool anyRgb = false, anyAlpha = false, readsDstAlpha = false;
        for (std::size_t i = 0; i < targets_.size(); ++i) {
            BlendState b = desc.blend[i];
            const int channels = formatInfo(targets_[i].format).channels;
            b.writeMask &= std::uint8_t((1u << channels) - 1u);  // channels the format lacks are not written
            masks[i] = b.writeMask;
            blendNeeded[i] = !b.isPlainWrite();
            anyRgb = anyRgb || (b.writeMask & WriteRGB);
            anyAlpha = anyAlpha || (b.writeMask & WriteA);
            readsDstAlpha = readsDstAlpha || rgbReadsDstAlpha(b);
        }
        const FailModePlan plan = planFailMode({desc.alphaTest, depthTest, depthWrite, desc.depth.func, anyRgb, anyAlpha,
                                                readsDstAlpha, options_.failModes == FailModeStrategy::PerTriangle});

        // The base state was applied when the pass began; within a pass only this backend
        // touches the context (a host sharing it changes state between passes, not inside one).
        glBindFramebuffer(GL_FRAMEBUFFER, passFbo_);
        glViewport(0, 0, passWidth_, passHeight_);
        glUseProgram(p);
        glBindVertexArray(fullscreen ? emptyVao_ : vao_);
        setParams(s, d.params);

        // Alpha test and alpha-to-coverage uniforms.
        glProgramUniform1i(p, s.alphaFunc, int(desc.alphaTest.func));
        glProgramUniform1f(p, s.alphaRef, desc.alphaTest.reference);
        const bool a2c = desc.alphaTest.alphaToCoverage && passSamples_ > 1;
        if (a2c && options_.nativeAlphaToCoverage) glEnable(GL_SAMPLE_ALPHA_TO_COVERAGE);
        else glDisable(GL_SAMPLE_ALPHA_TO_COVERAGE);
        const bool shaderA2c = a2c && !options_.nativeAlphaToCoverage;
        glProgramUniform1i(p, s.a2cSamples, shaderA2c ? passSamples_ : 0);
        glProgramUniform1i(p, s.a2cActual, passActualSamples_);

        // Depth, culling, scissor.
        if (depthTest) {
            glEnable(GL_DEPTH_TEST);
            glDepthFunc(glCompare(desc.depth.func));
        } else {
            glDisable(GL_DEPTH_TEST);
        }
        // Full-screen programs draw a triangle that the soft backend never culls.
        if (!fullscreen && desc.raster.cull != CullMode::None) {
            glEnable(GL_CULL_FACE);
            glCullFace(desc.raster.cull == CullMode::Back ? GL_BACK : GL_FRONT);
        } else {
            glDisable(GL_CULL_FACE);
        }
        // With an upper-left origin GL still decides facing on NDC winding (ARB_clip_control),
        // so counter-clockwise as displayed is GL_CCW.
        glFrontFace(desc.raster.frontFace == Winding::CounterClockwise ? GL_CCW : GL_CW);
        glEnable(GL_SCISSOR_TEST);
        Rect scissor{0, 0, passWidth_, passHeight_};
        if (d.scissor) {
            const int x0 = std::max(0, d.scissor->x), y0 = std::max(0, d.scissor->y);
            const int x1 = std::min(passWidth_, d.scissor->x + d.scissor->width);
            const int y1 = std::min(passHeight_, d.scissor->y + d.scissor->height);
            scissor = {x0, y0, std::max(0, x1 - x0), std::max(0, y1 - y0)};
        }
        if (scissor.empty()) return;
        glScissor(scissor.x, scissor.y, scissor.width, scissor.height);  // upper-left origin: y from the top
        if (passActualSamples_ > 1)
            glProgramUniform4i(p, s.scissor, scissor.x, scissor.y, scissor.x + scissor.width, scissor.y + scissor.height);
        else
            glProgramUniform4i(p, s.scissor, 0, 0, 0, 0);

        // Blending per target.
        for (std::size_t i = 0; i < targets_.size(); ++i) {
            const BlendState& b = desc.blend[i];
            if (!blendNeeded[i]) {
                glDisablei(GL_BLEND, GLuint(i));
                continue;
            }
            glEnablei(GL_BLEND, GLuint(i));
            glBlendFuncSeparatei(GLuint(i), glBlendFactor(b.srcRgb), glBlendFactor(b.dstRgb), glBlendFactor(b.srcAlpha),
                                 glBlendFactor(b.dstAlpha));
            glBlendEquationSeparatei(GLuint(i), glBlendOp(b.opRgb), glBlendOp(b.opAlpha));
        }
        glBlendColor(desc.blendConstant.r, desc.blendConstant.g, desc.blendConstant.b, desc.blendConstant.a);

        // Vertex input.
        if (!fullscreen) {
            glVertexArrayVertexBuffer(vao_, 0, buffers_.get(d.vertices).id, 0, sizeof(Vertex));
            glVertexArrayVertexBuffer(vao_, 1, d.instances ? buffers_.get(d.instances).id : identityInstance_, 0,
                                      sizeof(Instance));
            glVertexArrayElementBuffer(vao_, d.indices ? buffers_.get(d.indices).id : 0);
        }

        auto applyStep = [&](const PlanStep& step) {
            // A step that writes nothing is not drawn, unless an occlusion query counts its samples.
            bool writes = step.depthWrite || pass_->countSamplesInto;
            for (std::size_t i = 0; i < targets_.size(); ++i) {
                const std::uint8_t m = masks[i] & step.channels;
                writes = writes || m;
                glColorMaski(GLuint(i), (m & WriteR) != 0, (m & WriteG) != 0, (m & WriteB) != 0, (m & WriteA) != 0);
            }
            glDepthMask(step.depthWrite ? GL_TRUE : GL_FALSE);
            glProgramUniform1i(p, s.alphaSelect, step.select == FragmentSelect::All       ? kSelectAll
                                                 : step.select == FragmentSelect::Passing ? kSelectPassing
                                                                                          : kSelectFailing);
            return writes;
        };

        if (fullscreen) {
            for (const PlanStep& step : plan.steps)
                if (applyStep(step)) glDrawArrays(GL_TRIANGLES, 0, 3);
        } else if (d.count > 0) {
            if (plan.perTriangle) drawPerTriangle(d, plan, applyStep);
            else
                for (const PlanStep& step : plan.steps)
                    if (applyStep(step)) drawRange(d, d.first, d.count, 0, d.instanceCount);
        }
        // glGetError stalls a threaded driver and the message costs a string per draw: errors
        // are checked per draw only in debug builds or with debug output on, and always at the
        // end of the pass (endPass), which names the pass.
        if (kCheckEveryDraw || options_.debugOutput)
            checkGl("draw with pipeline " + quotedName(desc.name) + " in pass " + quotedName(pass_->name));
    }

    void drawRange(const DrawDesc& d, std::uint32_t first, std::uint32_t count, std::uint32_t baseInstance,
                   std::uint32_t instances) {
        if (d.indices)
            glDrawElementsInstancedBaseInstance(GL_TRIANGLES, GLsizei(count), GL_UNSIGNED_INT,
                                                reinterpret_cast<const void*>(std::uintptr_t(first) * 4),
                                                GLsizei(instances), baseInstance);
        else
            glDrawArraysInstancedBaseInstance(GL_TRIANGLES, GLint(first), GLsizei(count), GLsizei(instances), baseInstance);
    }

    // Exact fail modes: a triangle's fragments never overlap, so its passing and failing steps
    // commute; triangles go in the soft backend's order (instance-major).
    template <typename ApplyStep>
    void drawPerTriangle(const DrawDesc& d, const FailModePlan& plan, ApplyStep& applyStep) {
        for (std::uint32_t instance = 0; instance < d.instanceCount; ++instance)
            for (std::uint32_t tri = 0; tri < d.count / 3; ++tri)
                for (const PlanStep& step : plan.steps)
                    if (applyStep(step)) drawRange(d, d.first + tri * 3, 3, instance, 1);
    }

    GlOptions options_;
    std::shared_ptr<GlContext> context_;
    GlInfo info_;
    GlTextureLimits textureLimits_;
    int glMajor_ = 4, glMinor_ = 5;
    ResourcePool<TextureTag, GlTexture> textures_;
    ResourcePool<BufferTag, GlBuffer> buffers_;
    ResourcePool<PipelineTag, GlPipeline> pipelines_;
    ResourcePool<QueryTag, GlQuery> queries_;
    ResourcePool<ProgramTag, std::shared_ptr<const ProgramSlot>> programs_;
    ResourceLookup lookup_;  // what the shared validation reads
    std::set<GLuint> ownedTextures_, ownedBuffers_;
    std::map<GLenum, int> maxSamplesByFormat_;
    std::map<std::vector<GLuint>, GLuint> framebuffers_;
    std::array<std::shared_ptr<const ProgramSlot>, kStandardProgramCount> standardPrograms_;  // made on first use
    std::optional<ProgramSlot> resolveColor_, resolveDepth_, nothing_;
    std::array<GLuint, 27> samplers_{};
    GLuint vao_ = 0, emptyVao_ = 0, identityInstance_ = 0;

    std::optional<PassDesc> pass_;
    std::vector<Target> targets_;  // the pass's colour attachments, packed (soft: colorTargets)
    int passWidth_ = 0, passHeight_ = 0, passSamples_ = 1, passActualSamples_ = 1;
    GLuint passFbo_ = 0, passQuery_ = 0, passCondition_ = 0;
    std::vector<PendingTiming> pendingTimings_;
    std::set<GLuint> occlusionQueries_;  // every GL query object behind a QueryHandle, live or retired
    std::vector<GLuint> retiredQueries_;  // replaced while a pending timing reads them
};

}  // namespace

std::unique_ptr<GlBackend> createGlBackend(const GlOptions& options) {
    std::shared_ptr<GlContext> context = options.context;
    if (!context && !options.useCurrentContext) {
        HeadlessEglOptions headless = options.headless;
        headless.debug = headless.debug || options.debugOutput;
        context = HeadlessEglContext::create(headless);
    }
    if (options.useCurrentContext && context)
        throw Error("GL backend: both a context and useCurrentContext given; pick one");
    return std::make_unique<GlBackendImpl>(options, std::move(context));
}

}  // namespace engine::render::gl
