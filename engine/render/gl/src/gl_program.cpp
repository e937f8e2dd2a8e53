// SPDX-License-Identifier: MIT
#include "engine/render/gl/gl_program.hpp"

#include <algorithm>
#include <cstdio>
#include <optional>
#include <utility>

#include <epoxy/gl.h>

#include "engine/core/error.hpp"

namespace engine::render::gl {

GlProgram::GlProgram(GlProgram&& other) noexcept
    : name_(std::move(other.name_)), id_(std::exchange(other.id_, 0u)) {}

GlProgram& GlProgram::operator=(GlProgram&& other) noexcept {
    if (this != &other) {
        if (id_) glDeleteProgram(id_);
        name_ = std::move(other.name_);
        id_ = std::exchange(other.id_, 0u);
    }
    return *this;
}

GlProgram::~GlProgram() {
    if (id_) glDeleteProgram(id_);
}

int GlProgram::uniform(const char* name) const { return glGetUniformLocation(id_, name); }

namespace {

// A shader's or a program's info log when its `status` (GL_COMPILE_STATUS, GL_LINK_STATUS) is
// false, without the NULs and newlines drivers end it with; nothing when the status is true.
// getInteger/getLog: glGetShaderiv/glGetShaderInfoLog, or the program ones (same signatures).
std::optional<std::string> failureLog(GLuint object, GLenum status, PFNGLGETSHADERIVPROC getInteger,
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

GLuint compileStage(const std::string& name, GLenum stage, std::string_view source) {
    const GLuint shader = glCreateShader(stage);
    if (!shader) throw Error("GL program '" + name + "': glCreateShader failed (no current context?)");
    const GLchar* text = source.data();
    const GLint length = static_cast<GLint>(source.size());
    glShaderSource(shader, 1, &text, &length);
    glCompileShader(shader);
    if (const auto log = failureLog(shader, GL_COMPILE_STATUS, glGetShaderiv, glGetShaderInfoLog)) {
        glDeleteShader(shader);
        throw Error("GL program '" + name + "': " + (stage == GL_VERTEX_SHADER ? "vertex" : "fragment") +
                    " shader does not compile:\n" + *log);
    }
    return shader;
}

}  // namespace

GlProgram compileProgram(std::string name, std::string_view vertexSource, std::string_view fragmentSource) {
    const GLuint vs = compileStage(name, GL_VERTEX_SHADER, vertexSource);
    GLuint fs = 0;
    try {
        fs = compileStage(name, GL_FRAGMENT_SHADER, fragmentSource);
    } catch (...) {
        glDeleteShader(vs);
        throw;
    }
    const GLuint program = glCreateProgram();
    glAttachShader(program, vs);
    glAttachShader(program, fs);
    glLinkProgram(program);
    glDetachShader(program, vs);
    glDetachShader(program, fs);
    glDeleteShader(vs);
    glDeleteShader(fs);
    if (const auto log = failureLog(program, GL_LINK_STATUS, glGetProgramiv, glGetProgramInfoLog)) {
        glDeleteProgram(program);
        throw Error("GL program '" + name + "' does not link:\n" + *log);
    }
    return GlProgram(std::move(name), program);
}

const char* framebufferStatusName(unsigned int status) {
    switch (status) {
        case GL_FRAMEBUFFER_COMPLETE: return "GL_FRAMEBUFFER_COMPLETE";
        case GL_FRAMEBUFFER_UNDEFINED: return "GL_FRAMEBUFFER_UNDEFINED";
        case GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT: return "GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT";
        case GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT: return "GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT";
        case GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER: return "GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER";
        case GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER: return "GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER";
        case GL_FRAMEBUFFER_UNSUPPORTED: return "GL_FRAMEBUFFER_UNSUPPORTED";
        case GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE: return "GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE";
        case GL_FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS: return "GL_FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS";
        default: return "unknown framebuffer status";
    }
}

void checkFramebuffer(unsigned int framebuffer, const std::string& what) {
    const GLenum status = glCheckNamedFramebufferStatus(framebuffer, GL_DRAW_FRAMEBUFFER);
    if (status == GL_FRAMEBUFFER_COMPLETE) return;
    if (status == 0)
        throw Error(what + ": framebuffer status query failed (GL error 0x" + [] {
            char buf[16];
            std::snprintf(buf, sizeof buf, "%x", glGetError());
            return std::string(buf);
        }() + ")");
    throw Error(what + ": framebuffer incomplete (" + framebufferStatusName(status) + ")");
}

}  // namespace engine::render::gl
