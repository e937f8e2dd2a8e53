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

void loadFunctions(GlFunctions& gl, const Loader& load, Api api) {
    // Required: the first missing one is named (a loader for another API, or a GL 2 context).
#define SSAM_GL_LOAD_REQUIRED(type, name)                                                                     \
    gl.name = reinterpret_cast<type>(load("gl" #name));                                                       \
    if (!gl.name)                                                                                             \
        throw Failure(Status::MissingEntryPoint, "ssam::gl: the host's GL loader has no address for gl" #name \
                                                 " (an OpenGL 3.3 function SSAM needs)");
    SSAM_GL_REQUIRED_FUNCTIONS(SSAM_GL_LOAD_REQUIRED)
    ENGINE_GL_PROGRAM_FUNCTIONS(SSAM_GL_LOAD_REQUIRED)
    if (api == Api::Gl33) {
        SSAM_GL_DESKTOP_FUNCTIONS(SSAM_GL_LOAD_REQUIRED)
    }
#undef SSAM_GL_LOAD_REQUIRED
    // Optional: the core name, then the extensions' (ARB on desktop GL; OES, then EXT on ES); null
    // when none resolves. Which ones are usable is checkContext()'s to say.
    static constexpr const char* kDesktopSuffixes[] = {"", "ARB"};
    static constexpr const char* kEsSuffixes[] = {"", "OES", "EXT"};
    const auto optional = [&](const char* core) -> Loader::AnyFunction {
        const std::string name = core;
        const auto lookUp = [&](const auto& suffixes) -> Loader::AnyFunction {
            for (const char* suffix : suffixes)
                if (const Loader::AnyFunction f = load((name + suffix).c_str())) return f;
            return nullptr;
        };
        return api == Api::Gl33 ? lookUp(kDesktopSuffixes) : lookUp(kEsSuffixes);
    };
#define SSAM_GL_LOAD_OPTIONAL(type, name) gl.name = reinterpret_cast<type>(optional("gl" #name));
    if (api == Api::Gles30) {
        SSAM_GL_DESKTOP_FUNCTIONS(SSAM_GL_LOAD_OPTIONAL)
    }
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

void GlFunctions::colorMaskAt(GLuint buffer, GLboolean r, GLboolean g, GLboolean b, GLboolean a) const {
    if (indexedBuffers) ColorMaski(buffer, r, g, b, a);
    else if (buffer == 0) ColorMask(r, g, b, a);
}

namespace {

// An OpenGL ES context's GL_VERSION begins "OpenGL ES " (ES 3.0 §6.1.5; WebGL2's, through
// Emscripten, too); a desktop one's with the version number.
bool isEsVersion(const char* version) { return std::strncmp(version, "OpenGL ES ", 10) == 0; }

// The ES context's capabilities (Api::Gles30): what ES 3.0 leaves to extensions.
void checkEsContext(GlFunctions& gl) {
    const bool drawBuffersIndexed = gl.version >= 32 || gl.hasExtension("GL_OES_draw_buffers_indexed") ||
                                    gl.hasExtension("GL_EXT_draw_buffers_indexed");
    gl.indexedBuffers = drawBuffersIndexed && gl.ColorMaski && gl.Enablei && gl.Disablei && gl.IsEnabledi &&
                        gl.GetBooleani_v && gl.version >= 31;  // glGetBooleani_v: ES 3.1
    gl.perBufferBlend = drawBuffersIndexed && gl.BlendEquationi && gl.BlendEquationSeparatei && gl.BlendFuncSeparatei;
    gl.textureStorage = gl.TexStorage2D != nullptr;  // ES 3.0 core
    gl.clipControl = gl.hasExtension("GL_EXT_clip_control");
    gl.compatibility = false;
    // Asked for by name even on ES 3.2 (which made float formats renderable): Api::Gles30 keeps to
    // what an ES 3.0 / WebGL2 context says it has.
    gl.colorBufferFloat = gl.hasExtension("GL_EXT_color_buffer_float");
    gl.floatBlend = gl.colorBufferFloat && gl.hasExtension("GL_EXT_float_blend");
}

}  // namespace

std::string checkContext(GlFunctions& gl, Api api) {
    // Without a current context the loader's functions are no-ops (GLVND, Mesa, WGL): glGetString
    // answers null. Checked on every frame too, so a host that lost its context gets a status.
    const auto* version = reinterpret_cast<const char*>(gl.GetString(GL_VERSION));
    if (!version)
        throw Failure(Status::NoContext,
                      "ssam::gl: no OpenGL context is current on this thread "
                      "(glGetString(GL_VERSION) returned null)");
    const bool es = isEsVersion(version);
    if (es != (api == Api::Gles30))
        throw Failure(Status::InvalidArgument,
                      std::string("ssam::gl: initialize() was told Api::") + (api == Api::Gles30 ? "Gles30" : "Gl33") +
                          " but the current context is " + version + ": pass Api::" + (es ? "Gles30" : "Gl33"));
    GLint major = 0, minor = 0;
    gl.GetIntegerv(GL_MAJOR_VERSION, &major);
    gl.GetIntegerv(GL_MINOR_VERSION, &minor);
    gl.es = es;
    gl.version = major * 10 + minor;
    if (es) {
        if (major < 3)
            throw Failure(Status::NoContext,
                          std::string("ssam::gl: OpenGL ES 3.0 or newer needed, the current context is ") + version);
        checkEsContext(gl);
        const auto* renderer = reinterpret_cast<const char*>(gl.GetString(GL_RENDERER));
        return std::string(renderer ? renderer : "?") + ", " + version +
               (gl.perBufferBlend ? "; per-buffer blending" : "; no per-buffer blending (no rg16f mask)") +
               (gl.colorBufferFloat ? "" : "; no GL_EXT_color_buffer_float (no float masks or colour)");
    }
    GLint profile = 0;
    if (major > 3 || (major == 3 && minor >= 2)) gl.GetIntegerv(GL_CONTEXT_PROFILE_MASK, &profile);
    if (major < 3 || (major == 3 && minor < 3))
        throw Failure(Status::NoContext,
                      std::string("ssam::gl: OpenGL 3.3 or newer needed, the current context is ") + version);
    gl.indexedBuffers = gl.colorBufferFloat = gl.floatBlend = true;
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
