// SPDX-License-Identifier: MIT
#pragma once
// The name of a glCheckFramebufferStatus answer, for the errors of the engine's GL backend and of
// ssam::gl alike. Private to both, header-only: the includer brings its GL header first
// (<epoxy/gl.h> in the backend, <GL/glcorearb.h> in ssam::gl, which links no GL library).
#ifndef GL_FRAMEBUFFER_COMPLETE
#error "include <epoxy/gl.h> or <GL/glcorearb.h> before engine/render/gl/plumbing/framebuffer_status_name.hpp"
#endif

namespace engine::render::gl::plumbing {

// "GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT" etc.
inline const char* framebufferStatusName(GLenum status) {
    switch (status) {
        case GL_FRAMEBUFFER_COMPLETE: return "GL_FRAMEBUFFER_COMPLETE";
        case GL_FRAMEBUFFER_UNDEFINED: return "GL_FRAMEBUFFER_UNDEFINED";
        case GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT: return "GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT";
        case GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT: return "GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT";
#ifdef GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER  // desktop GL's (not in ES 3.0 / WebGL2)
        case GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER: return "GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER";
#endif
#ifdef GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER  // desktop GL's (not in ES 3.0 / WebGL2)
        case GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER: return "GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER";
#endif
        case GL_FRAMEBUFFER_UNSUPPORTED: return "GL_FRAMEBUFFER_UNSUPPORTED";
        case GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE: return "GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE";
#ifdef GL_FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS  // desktop GL's (not in ES 3.0 / WebGL2)
        case GL_FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS: return "GL_FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS";
#endif
        default: return "unknown framebuffer status";
    }
}

}  // namespace engine::render::gl::plumbing
