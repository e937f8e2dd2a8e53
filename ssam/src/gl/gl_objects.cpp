// SPDX-License-Identifier: MIT
#include "gl_objects.hpp"

#include <dlfcn.h>
#include <epoxy/gl.h>

#include <algorithm>
#include <cstdio>

#include "engine/core/error.hpp"

namespace ssam::gl {

namespace {

std::string infoLog(GLuint object, bool program) {
    GLint length = 0;
    program ? glGetProgramiv(object, GL_INFO_LOG_LENGTH, &length) : glGetShaderiv(object, GL_INFO_LOG_LENGTH, &length);
    std::string log(std::size_t(std::max(length, 1)), '\0');
    program ? glGetProgramInfoLog(object, length, nullptr, log.data())
            : glGetShaderInfoLog(object, length, nullptr, log.data());
    while (!log.empty() && (log.back() == '\0' || log.back() == '\n')) log.pop_back();
    return log;
}

GLuint compileStage(const std::string& name, GLenum stage, const char* source) {
    const GLuint shader = glCreateShader(stage);
    if (!shader) throw engine::Error("ssam_gl program '" + name + "': glCreateShader failed (no current context?)");
    glShaderSource(shader, 1, &source, nullptr);
    glCompileShader(shader);
    GLint ok = GL_FALSE;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        const std::string log = infoLog(shader, false);
        glDeleteShader(shader);
        throw engine::Error("ssam_gl program '" + name + "': " + (stage == GL_VERTEX_SHADER ? "vertex" : "fragment") +
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

bool hasCurrentContext() {
    // RTLD_NOLOAD: only a library the host already uses can hold its current context.
    auto current = [](const char* library, const char* function) {
        void* handle = dlopen(library, RTLD_LAZY | RTLD_NOLOAD);
        if (!handle) return false;
        using GetCurrent = void* (*)();
        const auto get = reinterpret_cast<GetCurrent>(dlsym(handle, function));
        const bool found = get && get() != nullptr;
        dlclose(handle);
        return found;
    };
    return current("libEGL.so.1", "eglGetCurrentContext") || current("libGLX.so.0", "glXGetCurrentContext") ||
           current("libGL.so.1", "glXGetCurrentContext");
}

unsigned int compileProgram(const std::string& name, const char* vertexSource, const char* fragmentSource) {
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
    glDeleteShader(vs);
    glDeleteShader(fs);
    GLint ok = GL_FALSE;
    glGetProgramiv(program, GL_LINK_STATUS, &ok);
    if (!ok) {
        const std::string log = infoLog(program, true);
        glDeleteProgram(program);
        throw engine::Error("ssam_gl program '" + name + "' does not link:\n" + log);
    }
    return program;
}

TextureInfo inspectTexture2D(unsigned int texture, const char* what) {
    if (texture == 0 || !glIsTexture(texture))
        throw engine::Error(std::string("ssam_gl: ") + what + " " + std::to_string(texture) +
                            " is not a GL texture name (0, deleted, or never bound)");
    GLint previous = 0;
    glGetIntegerv(GL_TEXTURE_BINDING_2D, &previous);
    while (glGetError() != GL_NO_ERROR) {
    }  // errors the host left pending would be taken for ours
    glBindTexture(GL_TEXTURE_2D, texture);
    if (glGetError() != GL_NO_ERROR) {
        glBindTexture(GL_TEXTURE_2D, static_cast<GLuint>(previous));
        throw engine::Error(std::string("ssam_gl: ") + what + " " + std::to_string(texture) +
                            " is not a GL_TEXTURE_2D (multisampled, array, cube... textures are not supported: "
                            "resolve to a single-sample 2D texture first)");
    }
    TextureInfo info;
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &info.width);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_HEIGHT, &info.height);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_INTERNAL_FORMAT, &info.internalFormat);
    glBindTexture(GL_TEXTURE_2D, static_cast<GLuint>(previous));
    return info;
}

void checkDrawFramebuffer(const char* what) {
    const GLenum status = glCheckFramebufferStatus(GL_DRAW_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE)
        throw engine::Error(std::string("ssam_gl: the ") + what + " framebuffer is incomplete: " +
                            framebufferStatusName(status));
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

}  // namespace ssam::gl
