// SPDX-License-Identifier: MIT
#pragma once
// Compiling and linking a GLSL program through a table of entry points, so the engine's GL
// backend (libepoxy) and ssam::gl (the host's loader: it links no GL library) build their programs
// with one piece of code and report a failure with the same text. Private to both, header-only
// and without a GL header of its own: the backend declares GL through libepoxy, ssam::gl through
// Khronos' <GL/glcorearb.h> alone, so the includer brings its header first.
#ifndef GL_COMPILE_STATUS
#error "include <epoxy/gl.h> or <GL/glcorearb.h> before engine/render/gl/plumbing/build_program.hpp"
#endif

#include <algorithm>
#include <optional>
#include <string>
#include <string_view>

namespace engine::render::gl::plumbing {

// The entry points buildProgram() calls, as X(type, name without the gl prefix): a loader fills a
// table from the list, and the list declares ProgramFunctions.
#define ENGINE_GL_PROGRAM_FUNCTIONS(X)               \
    X(PFNGLATTACHSHADERPROC, AttachShader)           \
    X(PFNGLCOMPILESHADERPROC, CompileShader)         \
    X(PFNGLCREATEPROGRAMPROC, CreateProgram)         \
    X(PFNGLCREATESHADERPROC, CreateShader)           \
    X(PFNGLDELETEPROGRAMPROC, DeleteProgram)         \
    X(PFNGLDELETESHADERPROC, DeleteShader)           \
    X(PFNGLDETACHSHADERPROC, DetachShader)           \
    X(PFNGLGETPROGRAMINFOLOGPROC, GetProgramInfoLog) \
    X(PFNGLGETPROGRAMIVPROC, GetProgramiv)           \
    X(PFNGLGETSHADERINFOLOGPROC, GetShaderInfoLog)   \
    X(PFNGLGETSHADERIVPROC, GetShaderiv)             \
    X(PFNGLLINKPROGRAMPROC, LinkProgram)             \
    X(PFNGLSHADERSOURCEPROC, ShaderSource)

struct ProgramFunctions {
#define ENGINE_GL_PROGRAM_DECLARE(type, name) type name = nullptr;
    ENGINE_GL_PROGRAM_FUNCTIONS(ENGINE_GL_PROGRAM_DECLARE)
#undef ENGINE_GL_PROGRAM_DECLARE
};

// A linked program object, or 0 and why not (each caller throws its own error type with it).
struct [[nodiscard]] BuiltProgram {
    GLuint id = 0;
    std::string error;
};

namespace build_detail {

// A shader's or a program's info log when its `status` (GL_COMPILE_STATUS, GL_LINK_STATUS) is
// false, without the NULs and newlines drivers end it with; nothing when the status is true.
// The shader and program getters share their signatures.
inline std::optional<std::string> failureLog(GLuint object, GLenum status, PFNGLGETSHADERIVPROC getInteger,
                                             PFNGLGETSHADERINFOLOGPROC getLog) {
    GLint ok = GL_FALSE;
    getInteger(object, status, &ok);
    if (ok) return std::nullopt;
    GLint length = 0;
    getInteger(object, GL_INFO_LOG_LENGTH, &length);
    std::string log(std::size_t(std::max(length, 1)), '\0');
    getLog(object, length, nullptr, log.data());
    while (!log.empty() && (log.back() == '\0' || log.back() == '\n')) log.pop_back();
    return log;
}

// A compiled shader object, or 0 with `error` set.
inline GLuint compileStage(const ProgramFunctions& gl, const std::string& label, GLenum stage, std::string_view source,
                           std::string& error) {
    const GLuint shader = gl.CreateShader(stage);
    if (!shader) {
        error = label + ": glCreateShader failed (no current context?)";
        return 0;
    }
    const GLchar* text = source.data();
    const auto length = static_cast<GLint>(source.size());
    gl.ShaderSource(shader, 1, &text, &length);
    gl.CompileShader(shader);
    if (const auto log = failureLog(shader, GL_COMPILE_STATUS, gl.GetShaderiv, gl.GetShaderInfoLog)) {
        gl.DeleteShader(shader);
        error =
            label + ": " + (stage == GL_VERTEX_SHADER ? "vertex" : "fragment") + " shader does not compile:\n" + *log;
        return 0;
    }
    return shader;
}

}  // namespace build_detail

// Compiles both stages and links them. `label` starts every error ("GL program 'sky'"), which
// goes on with the stage that does not compile or "does not link", then the info log. Nothing
// is left behind on failure; on success the shader objects are already deleted.
inline BuiltProgram buildProgram(const ProgramFunctions& gl, const std::string& label, std::string_view vertexSource,
                                 std::string_view fragmentSource) {
    BuiltProgram built;
    const GLuint vs = build_detail::compileStage(gl, label, GL_VERTEX_SHADER, vertexSource, built.error);
    if (!vs) return built;
    const GLuint fs = build_detail::compileStage(gl, label, GL_FRAGMENT_SHADER, fragmentSource, built.error);
    if (!fs) {
        gl.DeleteShader(vs);
        return built;
    }
    const GLuint program = gl.CreateProgram();
    gl.AttachShader(program, vs);
    gl.AttachShader(program, fs);
    gl.LinkProgram(program);
    // Detached, the shader objects go now rather than with the program.
    gl.DetachShader(program, vs);
    gl.DetachShader(program, fs);
    gl.DeleteShader(vs);
    gl.DeleteShader(fs);
    if (const auto log = build_detail::failureLog(program, GL_LINK_STATUS, gl.GetProgramiv, gl.GetProgramInfoLog)) {
        gl.DeleteProgram(program);
        built.error = label + " does not link:\n" + *log;
        return built;
    }
    built.id = program;
    return built;
}

}  // namespace engine::render::gl::plumbing
