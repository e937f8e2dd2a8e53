// SPDX-License-Identifier: MIT
// The GLES driver's life: the ES context and its extensions, the vertex array every mesh draw
// uses, and the release of every GL object it made. The rest of GlesDriver: gles_driver.hpp.
#include "gles_driver.hpp"

#if !defined(__EMSCRIPTEN__)
#include <dlfcn.h>
#endif

#include <cstddef>
#include <string>
#include <utility>

#include "engine/core/error.hpp"
#include "engine/core/log.hpp"
#include "engine/render/vertex.hpp"
#include "gl_check.hpp"

namespace engine::render::gles {

using gl::checkGl;
using gl::drainGlErrors;

GlesDriver::GlesDriver(const GlesOptions& options, std::shared_ptr<gl::GlContext> context)
    : options_(options), context_(std::move(context)), framebuffers_(makeBoundFramebuffer) {
    makeCurrent();
    const char* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
    if (!version) throw Error("GLES backend: no GL context is current on this thread");
    version_ = version;
    if (gl::glIsDesktop() || gl::glVersion() < 30)
        throw Error("GLES backend: OpenGL ES 3.0 or newer needed, the context is " + version_);
    renderer_ = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    // ES 3.0 has no glClipControl: without EXT_clip_control every vertex stage ends by changing
    // its clip position to what the extension's origin and depth mode give (why it is the same
    // picture and depth: gles_shaders.cpp), and front faces are decided reversed (gles_draw.cpp).
    extensions_.clipControl = gl::glHasExtension("GL_EXT_clip_control");
    extensions_.colorBufferFloat = gl::glHasExtension("GL_EXT_color_buffer_float");
    extensions_.floatBlend = gl::glHasExtension("GL_EXT_float_blend");
    extensions_.drawBuffersIndexed = gl::glHasExtension("GL_OES_draw_buffers_indexed");
    extensions_.floatLinear = gl::glHasExtension("GL_OES_texture_float_linear");
    textureLimits_ = gl::queryGlTextureLimits(renderer_, true);

    drainGlErrors();
    glGenVertexArrays(1, &emptyVao_);  // full-screen and internal draws: no vertex input
    glGenVertexArrays(1, &vao_);
    glBindVertexArray(vao_);
    // Vertex (locations 0-3, per vertex) and Instance (4-8, per instance); their buffers and
    // offsets are given per draw (bindVertices): ES 3.0 has no separate vertex bindings.
    for (GLuint location = 0; location <= 8; ++location) glEnableVertexAttribArray(location);
    for (GLuint location = 4; location <= 8; ++location) glVertexAttribDivisor(location, 1);
    glBindVertexArray(0);
    const Instance identity{};
    glGenBuffers(1, &identityInstance_);
    glBindBuffer(GL_ARRAY_BUFFER, identityInstance_);
    glBufferData(GL_ARRAY_BUFFER, sizeof identity, &identity, GL_STATIC_DRAW);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    checkGl("GLES backend: creating the vertex layout");
    log::debug("GLES backend: ", describe());
}

GlesDriver::~GlesDriver() {
    try {
        makeCurrent();
    } catch (const Error& e) {
        log::warn("GLES backend: cannot make the context current to release objects: ", e.what());
        return;
    }
    framebuffers_.release();
    textures_.forEach(deleteStorage);
    buffers_.forEach([](const GlBuffer& b) { glDeleteBuffers(1, &b.id); });
    queries_.forEach([](const GlQuery& q) {
        if (q.id) glDeleteQueries(1, &q.id);
    });
    samplers_.release();
    glDeleteTextures(1, &presentCopy_.texture);
    glDeleteBuffers(1, &presentCopy_.pixels);
    glDeleteBuffers(1, &identityInstance_);
    glDeleteVertexArrays(1, &vao_);
    glDeleteVertexArrays(1, &emptyVao_);
    programs_ = {};  // program objects are deleted while the context is current
    depthToColor_.reset();
}

std::string GlesDriver::describe() const {
    return "gles: " + renderer_ + ", " + version_ +
           " (pass times: CPU wall time of recording, ES has no timer query; " +
           (extensions_.clipControl ? "upper-left origin and depth in [0, 1] by EXT_clip_control"
                                    : "depth and origin remapped in the vertex stage: no EXT_clip_control") +
           ")";
}

namespace {

#if defined(__EMSCRIPTEN__)
// On the web the page makes the WebGL2 context (there is no EGL) and hands it over.
std::shared_ptr<gl::GlContext> contextFor(const GlesOptions& options) {
    if (!options.context)
        throw Error("GLES backend: in a browser the page makes the WebGL2 context; pass it as GlesOptions::context");
    return options.context;
}
#else
// libepoxy aborts the process when it cannot load the ES library: look for it first.
std::string esLibraryMissing() {
    static const bool found = dlopen("libGLESv2.so.2", RTLD_LAZY | RTLD_LOCAL) != nullptr;  // kept loaded
    return found ? std::string() : "libGLESv2.so.2 cannot be loaded (Debian: libgles2)";
}

std::shared_ptr<gl::GlContext> contextFor(const GlesOptions& options) {
    if (options.context) return options.context;
    if (std::string why = esLibraryMissing(); !why.empty()) throw Error("GLES backend: " + why);
    gl::HeadlessEglOptions headless = options.headless;
    headless.es = true;
    return gl::HeadlessEglContext::create(headless);
}
#endif

}  // namespace

std::unique_ptr<Device> createGlesBackend(const GlesOptions& options) {
    return std::make_unique<Device>(std::make_unique<GlesDriver>(options, contextFor(options)));
}

std::string glesUnavailableReason(const GlesOptions& options) {
    try {
        createGlesBackend(options);
        return {};
    } catch (const Error& e) {
        return e.what();
    }
}

}  // namespace engine::render::gles
