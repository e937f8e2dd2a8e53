// SPDX-License-Identifier: MIT
// The GL driver's life: the context it needs, the vertex layout every mesh draw uses, and
// the release of every GL object it made. The rest of GlDriverImpl: gl_backend_impl.hpp.
#include <cstddef>
#include <string>
#include <utility>

#include "engine/core/error.hpp"
#include "engine/core/log.hpp"
#include "engine/render/vertex.hpp"
#include "gl_backend_impl.hpp"
#include "gl_check.hpp"

namespace engine::render::gl {
namespace {

void KHRONOS_APIENTRY onDebugMessage(GLenum, GLenum type, GLuint id, GLenum severity, GLsizei, const GLchar* message,
                                     const void*) {
    if (severity == GL_DEBUG_SEVERITY_NOTIFICATION) return;
    if (type == GL_DEBUG_TYPE_ERROR) log::warn("GL debug (id ", id, "): ", message);
    else log::debug("GL debug (id ", id, "): ", message);
}

}  // namespace

GlDriverImpl::GlDriverImpl(const GlOptions& options, std::shared_ptr<GlContext> context)
    : options_(options), context_(std::move(context)) {
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
        for (const char* ext :
             {"GL_ARB_clip_control", "GL_ARB_direct_state_access", "GL_ARB_buffer_storage", "GL_ARB_clear_texture"})
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

GlDriverImpl::~GlDriverImpl() {
    try {
        makeCurrent();
    } catch (const Error& e) {
        log::warn("GL backend: cannot make the context current to release objects: ", e.what());
        return;
    }
    framebuffers_.release();
    for (GLuint t : ownedTextures_) glDeleteTextures(1, &t);
    for (GLuint b : ownedBuffers_) glDeleteBuffers(1, &b);
    samplers_.release();
    for (const PendingTiming& p : pendingTimings_) glDeleteQueries(1, &p.query);
    if (passQuery_) glDeleteQueries(1, &passQuery_);
    for (GLuint q : occlusionQueries_) glDeleteQueries(1, &q);
    glDeleteBuffers(1, &identityInstance_);
    glDeleteVertexArrays(1, &vao_);
    glDeleteVertexArrays(1, &emptyVao_);
    // GL program objects are deleted while the context is current.
    programs_ = {};
    resolveColor_.reset();
    resolveDepth_.reset();
    nothing_.reset();
}

std::unique_ptr<Device> createGlBackend(const GlOptions& options) {
    std::shared_ptr<GlContext> context = options.context;
    if (!context && !options.useCurrentContext) {
        HeadlessEglOptions headless = options.headless;
        headless.debug = headless.debug || options.debugOutput;
        context = HeadlessEglContext::create(headless);
    }
    if (options.useCurrentContext && context)
        throw Error("GL backend: both a context and useCurrentContext given; pick one");
    return std::make_unique<Device>(std::make_unique<GlDriverImpl>(options, std::move(context)));
}

TextureHandle importTexture(Device& device, unsigned int id, const TextureDesc& desc) {
    GlDriver& gl = device.driverAs<GlDriver>();
    const std::string what = "imported texture " + quotedName(desc.name);
    return device.adoptTexture(desc, what, [&] { return gl.wrapTexture(id, desc, what); });
}

unsigned int glTexture(const Device& device, TextureHandle texture) {
    return device.driverAs<GlDriver>().glTexture(device.nativeTexture(texture));
}

}  // namespace engine::render::gl
