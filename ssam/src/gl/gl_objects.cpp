// SPDX-License-Identifier: MIT
#include "gl_objects.hpp"

#include <algorithm>
#include <cstdio>

#include "failure.hpp"
#include "gl_functions.hpp"

namespace ssam::gl::detail {

namespace {

std::string infoLog(const GlFunctions& gl, GLuint object, bool program) {
    GLint length = 0;
    program ? gl.GetProgramiv(object, GL_INFO_LOG_LENGTH, &length)
            : gl.GetShaderiv(object, GL_INFO_LOG_LENGTH, &length);
    std::string log(std::size_t(std::max(length, 1)), '\0');
    program ? gl.GetProgramInfoLog(object, length, nullptr, log.data())
            : gl.GetShaderInfoLog(object, length, nullptr, log.data());
    while (!log.empty() && (log.back() == '\0' || log.back() == '\n')) log.pop_back();
    return log;
}

GLuint compileStage(const GlFunctions& gl, const std::string& name, GLenum stage, const char* source) {
    const GLuint shader = gl.CreateShader(stage);
    if (!shader) throw Failure(Status::ShaderFailed, "ssam::gl program '" + name + "': glCreateShader failed");
    gl.ShaderSource(shader, 1, &source, nullptr);
    gl.CompileShader(shader);
    GLint ok = GL_FALSE;
    gl.GetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        const std::string log = infoLog(gl, shader, false);
        gl.DeleteShader(shader);
        throw Failure(Status::ShaderFailed, "ssam::gl program '" + name +
                                                "': " + (stage == GL_VERTEX_SHADER ? "vertex" : "fragment") +
                                                " shader does not compile:\n" + log);
    }
    return shader;
}

const char* framebufferStatusName(GLenum status) {
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

}  // namespace

unsigned int compileProgram(const GlFunctions& gl, const std::string& name, const char* vertexSource,
                            const char* fragmentSource) {
    const GLuint vs = compileStage(gl, name, GL_VERTEX_SHADER, vertexSource);
    GLuint fs = 0;
    try {
        fs = compileStage(gl, name, GL_FRAGMENT_SHADER, fragmentSource);
    } catch (...) {
        gl.DeleteShader(vs);
        throw;
    }
    const GLuint program = gl.CreateProgram();
    gl.AttachShader(program, vs);
    gl.AttachShader(program, fs);
    gl.LinkProgram(program);
    gl.DeleteShader(vs);
    gl.DeleteShader(fs);
    GLint ok = GL_FALSE;
    gl.GetProgramiv(program, GL_LINK_STATUS, &ok);
    if (!ok) {
        const std::string log = infoLog(gl, program, true);
        gl.DeleteProgram(program);
        throw Failure(Status::ShaderFailed, "ssam::gl program '" + name + "' does not link:\n" + log);
    }
    return program;
}

TextureInfo inspectTexture2D(const GlFunctions& gl, unsigned int texture, const char* what) {
    if (texture == 0 || !gl.IsTexture(texture))
        throw Failure(Status::InvalidTexture, std::string("ssam::gl: ") + what + " " + std::to_string(texture) +
                            " is not a GL texture name (0, deleted, or never bound)");
    GLint previous = 0;
    gl.GetIntegerv(GL_TEXTURE_BINDING_2D, &previous);
    // An error the host left pending would be taken for ours (reported at the frame's start);
    // bounded, as a lost context may answer GL_CONTEXT_LOST forever.
    for (int i = 0; i < 16 && gl.GetError() != GL_NO_ERROR; ++i) {
    }
    gl.BindTexture(GL_TEXTURE_2D, texture);
    if (gl.GetError() != GL_NO_ERROR) {
        gl.BindTexture(GL_TEXTURE_2D, static_cast<GLuint>(previous));
        throw Failure(Status::InvalidTexture, std::string("ssam::gl: ") + what + " " + std::to_string(texture) +
                            " is not a GL_TEXTURE_2D (multisampled, array, cube... textures are not supported: "
                            "resolve to a single-sample 2D texture first)");
    }
    TextureInfo info;
    gl.GetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &info.width);
    gl.GetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_HEIGHT, &info.height);
    gl.GetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_INTERNAL_FORMAT, &info.internalFormat);
    gl.BindTexture(GL_TEXTURE_2D, static_cast<GLuint>(previous));
    return info;
}

void checkDrawFramebuffer(const GlFunctions& gl, const char* what) {
    const GLenum status = gl.CheckFramebufferStatus(GL_DRAW_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE)
        throw Failure(
            Status::IncompleteFramebuffer,
            std::string("ssam::gl: the ") + what + " framebuffer is incomplete: " + framebufferStatusName(status));
}

const char* internalFormatName(int internalFormat) {
    switch (internalFormat) {
        case GL_RGBA8: return "GL_RGBA8";
        case GL_SRGB8_ALPHA8: return "GL_SRGB8_ALPHA8";
        case GL_RGBA16F: return "GL_RGBA16F";
        case GL_RGBA32F: return "GL_RGBA32F";
        case GL_RGB8: return "GL_RGB8";
        case GL_RGBA: return "GL_RGBA";
        case GL_R8: return "GL_R8";
        case GL_DEPTH_COMPONENT16: return "GL_DEPTH_COMPONENT16";
        case GL_DEPTH_COMPONENT24: return "GL_DEPTH_COMPONENT24";
        case GL_DEPTH_COMPONENT32F: return "GL_DEPTH_COMPONENT32F";
        case GL_DEPTH24_STENCIL8: return "GL_DEPTH24_STENCIL8";
        case GL_DEPTH32F_STENCIL8: return "GL_DEPTH32F_STENCIL8";
        default: break;
    }
    static thread_local char hex[16];
    std::snprintf(hex, sizeof hex, "0x%04X", static_cast<unsigned>(internalFormat));
    return hex;
}

}  // namespace ssam::gl::detail
