// SPDX-License-Identifier: MIT
#include "gl_functions.hpp"

#include <cstring>

#include "failure.hpp"

namespace ssam::gl::detail {

Loader::AnyFunction Loader::operator()(const char* name) const {
    if (returningFunction) return returningFunction(name);
    // A data pointer to a function pointer: what every void*-returning GL loader hands out
    // (conditionally supported by C++, defined by POSIX dlsym and by every GL platform).
    return returningPointer ? reinterpret_cast<AnyFunction>(returningPointer(name)) : nullptr;
}

void loadFunctions(GlFunctions& gl, const Loader& load) {
    // Required: the first missing one is named (a loader for another API, or a GL 2 context).
#define SSAM_GL_LOAD_REQUIRED(type, name)                                                                     \
    gl.name = reinterpret_cast<type>(load("gl" #name));                                                       \
    if (!gl.name)                                                                                             \
        throw Failure(Status::MissingEntryPoint, "ssam::gl: the host's GL loader has no address for gl" #name \
                                                 " (an OpenGL 3.3 function SSAM needs)");
    SSAM_GL_REQUIRED_FUNCTIONS(SSAM_GL_LOAD_REQUIRED)
    ENGINE_GL_PROGRAM_FUNCTIONS(SSAM_GL_LOAD_REQUIRED)
#undef SSAM_GL_LOAD_REQUIRED
    // Optional: the core name, then the ARB extension's; null when neither resolves.
#define SSAM_GL_LOAD_OPTIONAL(type, name)               \
    gl.name = reinterpret_cast<type>(load("gl" #name)); \
    if (!gl.name) gl.name = reinterpret_cast<type>(load("gl" #name "ARB"));
    SSAM_GL_OPTIONAL_FUNCTIONS(SSAM_GL_LOAD_OPTIONAL)
#undef SSAM_GL_LOAD_OPTIONAL
}

bool GlFunctions::hasExtension(const char* name) const {
    GLint count = 0;
    GetIntegerv(GL_NUM_EXTENSIONS, &count);
    for (GLint i = 0; i < count; ++i) {
        const auto* extension = reinterpret_cast<const char*>(GetStringi(GL_EXTENSIONS, static_cast<GLuint>(i)));
        if (extension && std::strcmp(extension, name) == 0) return true;
    }
    return false;
}

std::string checkContext(GlFunctions& gl) {
    // Without a current context the loader's functions are no-ops (GLVND, Mesa, WGL): glGetString
    // answers null. Checked on every frame too, so a host that lost its context gets a status.
    const auto* version = reinterpret_cast<const char*>(gl.GetString(GL_VERSION));
    if (!version)
        throw Failure(Status::NoContext,
                      "ssam::gl: no OpenGL context is current on this thread "
                      "(glGetString(GL_VERSION) returned null)");
    GLint major = 0, minor = 0;
    gl.GetIntegerv(GL_MAJOR_VERSION, &major);
    gl.GetIntegerv(GL_MINOR_VERSION, &minor);
    GLint profile = 0;
    if (major > 3 || (major == 3 && minor >= 2)) gl.GetIntegerv(GL_CONTEXT_PROFILE_MASK, &profile);
    if (major < 3 || (major == 3 && minor < 3))
        throw Failure(Status::NoContext,
                      std::string("ssam::gl: OpenGL 3.3 or newer needed, the current context is ") + version);
    gl.version = major * 10 + minor;
    gl.perBufferBlend = gl.BlendEquationi && gl.BlendEquationSeparatei && gl.BlendFuncSeparatei &&
                        (gl.version >= 40 || gl.hasExtension("GL_ARB_draw_buffers_blend"));
    gl.textureStorage = gl.TexStorage2D && (gl.version >= 42 || gl.hasExtension("GL_ARB_texture_storage"));
    gl.clipControl = gl.version >= 45 || gl.hasExtension("GL_ARB_clip_control");
    gl.compatibility = (profile & GL_CONTEXT_COMPATIBILITY_PROFILE_BIT) != 0;
    const auto* renderer = reinterpret_cast<const char*>(gl.GetString(GL_RENDERER));
    return std::string(renderer ? renderer : "?") + ", OpenGL " + version +
           (gl.compatibility ? " (compatibility)" : "") +
           (gl.perBufferBlend ? "; per-buffer blending" : "; no per-buffer blending (no rg16f mask)");
}

}  // namespace ssam::gl::detail
