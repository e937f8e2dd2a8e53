// SPDX-License-Identifier: MIT
#include "gl_objects.hpp"

#include <cstdio>

#include <GL/glcorearb.h>

#include "engine/render/gl/plumbing/framebuffer_status_name.hpp"
#include "failure.hpp"
#include "gl_functions.hpp"
#include "shaders.hpp"

namespace ssam::gl::detail {

unsigned int compileProgram(const GlFunctions& gl, const std::string& name, const char* vertexSource,
                            const char* fragmentSource) {
    const std::string head = shaders::glslHead(gl);
    auto built = engine::render::gl::plumbing::buildProgram(
        gl, "ssam::gl program '" + name + "'", (head + vertexSource).c_str(), (head + fragmentSource).c_str());
    if (!built.id) throw Failure(Status::ShaderFailed, built.error);
    return built.id;
}

void locateUniforms(const GlFunctions& gl, unsigned int program, std::initializer_list<UniformSlot> slots) {
    for (const UniformSlot& slot : slots) *slot.location = gl.GetUniformLocation(program, slot.name);
}

namespace {

// OpenGL ES 3.0 cannot ask a texture its format or size (glGetTexLevelParameteriv is ES 3.1): the
// format is read from the texture attached to a framebuffer (ES 3.0 §6.1.13: component sizes,
// type and encoding), the size is left unknown (-1). A format SSAM does not take reads as 0.
TextureInfo inspectAttached(const GlFunctions& gl, GLuint texture, TextureRole role) {
    GLint previous = 0;
    GLuint fbo = 0;
    gl.GetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &previous);
    gl.GenFramebuffers(1, &fbo);
    gl.BindFramebuffer(GL_READ_FRAMEBUFFER, fbo);
    const GLenum attachment = role == TextureRole::Depth ? GL_DEPTH_ATTACHMENT : GL_COLOR_ATTACHMENT0;
    gl.FramebufferTexture2D(GL_READ_FRAMEBUFFER, attachment, GL_TEXTURE_2D, texture, 0);
    const auto get = [&](GLenum what) {
        GLint value = 0;
        gl.GetFramebufferAttachmentParameteriv(GL_READ_FRAMEBUFFER, attachment, what, &value);
        return value;
    };
    const bool isFloat = get(GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE) == GL_FLOAT;
    TextureInfo info{-1, -1, 0};
    if (role == TextureRole::Depth) {
        const GLint depth = get(GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE);
        const bool stencil = get(GL_FRAMEBUFFER_ATTACHMENT_STENCIL_SIZE) == 8;
        if (depth == 16 && !stencil) info.internalFormat = GL_DEPTH_COMPONENT16;
        else if (depth == 24) info.internalFormat = stencil ? GL_DEPTH24_STENCIL8 : GL_DEPTH_COMPONENT24;
        else if (depth == 32 && isFloat) info.internalFormat = stencil ? GL_DEPTH32F_STENCIL8 : GL_DEPTH_COMPONENT32F;
    } else {
        const GLint bits = get(GL_FRAMEBUFFER_ATTACHMENT_RED_SIZE);
        const bool rgba = get(GL_FRAMEBUFFER_ATTACHMENT_GREEN_SIZE) == bits &&
                          get(GL_FRAMEBUFFER_ATTACHMENT_BLUE_SIZE) == bits &&
                          get(GL_FRAMEBUFFER_ATTACHMENT_ALPHA_SIZE) == bits;
        const bool srgb = get(GL_FRAMEBUFFER_ATTACHMENT_COLOR_ENCODING) == GL_SRGB;
        if (rgba && bits == 8 && !isFloat) info.internalFormat = srgb ? GL_SRGB8_ALPHA8 : GL_RGBA8;
        else if (rgba && isFloat && (bits == 16 || bits == 32))
            info.internalFormat = bits == 16 ? GL_RGBA16F : GL_RGBA32F;
    }
    gl.BindFramebuffer(GL_READ_FRAMEBUFFER, static_cast<GLuint>(previous));
    gl.DeleteFramebuffers(1, &fbo);
    return info;
}

}  // namespace

TextureInfo inspectTexture2D(const GlFunctions& gl, unsigned int texture, const char* what, TextureRole role) {
    if (texture == 0 || !gl.IsTexture(texture))
        throw Failure(Status::InvalidTexture, std::string("ssam::gl: ") + what + " " + std::to_string(texture) +
                                                  " is not a GL texture name (0, deleted, or never bound)");
    GLint previous = 0;
    gl.GetIntegerv(GL_TEXTURE_BINDING_2D, &previous);
    // An error the host left pending would be taken for ours (reported at the frame's start);
    // bounded, as a lost context may answer GL_CONTEXT_LOST forever.
    for (int i = 0; i < 16 && gl.GetError() != GL_NO_ERROR; ++i) {}
    gl.BindTexture(GL_TEXTURE_2D, texture);
    if (gl.GetError() != GL_NO_ERROR) {
        gl.BindTexture(GL_TEXTURE_2D, static_cast<GLuint>(previous));
        throw Failure(Status::InvalidTexture,
                      std::string("ssam::gl: ") + what + " " + std::to_string(texture) +
                          " is not a GL_TEXTURE_2D (multisampled, array, cube... textures are not supported: "
                          "resolve to a single-sample 2D texture first)");
    }
    if (gl.es) {
        gl.BindTexture(GL_TEXTURE_2D, static_cast<GLuint>(previous));
        return inspectAttached(gl, texture, role);
    }
    TextureInfo info;
    gl.GetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &info.width);
    gl.GetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_HEIGHT, &info.height);
    gl.GetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_INTERNAL_FORMAT, &info.internalFormat);
    gl.BindTexture(GL_TEXTURE_2D, static_cast<GLuint>(previous));
    return info;
}

TextureInfo inspectRenderbuffer(const GlFunctions& gl, unsigned int renderbuffer, const char* what) {
    const std::string name = std::string("ssam::gl: ") + what + " " + std::to_string(renderbuffer);
    if (renderbuffer == 0 || !gl.IsRenderbuffer(renderbuffer))
        throw Failure(Status::InvalidTexture,
                      name + (renderbuffer != 0 && gl.IsTexture(renderbuffer)
                                  ? " is not a renderbuffer but a texture: pass it as FrameDesc::depthTexture"
                                  : " is not a GL renderbuffer name (0, deleted, or never bound)"));
    GLint previous = 0, samples = 0;
    gl.GetIntegerv(GL_RENDERBUFFER_BINDING, &previous);
    gl.BindRenderbuffer(GL_RENDERBUFFER, renderbuffer);
    TextureInfo info;
    gl.GetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_WIDTH, &info.width);
    gl.GetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_HEIGHT, &info.height);
    gl.GetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_INTERNAL_FORMAT, &info.internalFormat);
    gl.GetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_SAMPLES, &samples);
    gl.BindRenderbuffer(GL_RENDERBUFFER, static_cast<GLuint>(previous));
    // On ES the host cannot do the paper's closest-sample downsample (§3.5.1) either: ES 3.0 reads
    // no multisampled depth per sample; its resolve blit keeps one sample of the implementation's choice.
    if (samples > 0)
        throw Failure(Status::InvalidTexture,
                      name + " is multisampled (" + std::to_string(samples) +
                          " samples): resolve it into a single-sample depth first" +
                          (gl.es ? " (OpenGL ES 3.0 cannot read a multisampled depth per sample, so the closest-"
                                   "sample downsample of [Hathaway 2010] 3.5.1 is not possible there: resolve "
                                   "with glBlitFramebuffer, which keeps one sample)"
                                 : ""));
    return info;
}

void checkDrawFramebuffer(const GlFunctions& gl, const char* what) {
    const GLenum status = gl.CheckFramebufferStatus(GL_DRAW_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE)
        throw Failure(Status::IncompleteFramebuffer,
                      std::string("ssam::gl: the ") + what +
                          " framebuffer is incomplete: " + engine::render::gl::plumbing::framebufferStatusName(status));
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
        case 0: return "one SSAM does not take (read through a framebuffer attachment on OpenGL ES 3.0)";
        default: break;
    }
    static thread_local char hex[16];
    std::snprintf(hex, sizeof hex, "0x%04X", static_cast<unsigned>(internalFormat));
    return hex;
}

}  // namespace ssam::gl::detail
