// SPDX-License-Identifier: MIT
#pragma once
// Small GL helpers of ssam_gl: program compilation, texture inspection, framebuffer checks.
// ssam_gl has its own (rather than engine/render/gl's) so it depends on nothing but libepoxy.
#include <string>

namespace ssam::gl {

// Whether a GLX or EGL context is current on this thread, asked of the libraries the process
// already has loaded. libepoxy aborts the process when a GL function is first called without a
// current context, so this is checked before any GL call.
bool hasCurrentContext();

// Compiles and links; engine::Error naming the program and stage with the info log.
unsigned int compileProgram(const std::string& name, const char* vertexSource, const char* fragmentSource);

struct TextureInfo {
    int width = 0, height = 0;
    int internalFormat = 0;
};

// Level 0 of a GL_TEXTURE_2D; engine::Error naming `what` when the name is not a texture or
// not a 2D one. Restores the active unit's GL_TEXTURE_2D binding.
TextureInfo inspectTexture2D(unsigned int texture, const char* what);

// engine::Error naming `what` and the status when the bound draw framebuffer is incomplete.
void checkDrawFramebuffer(const char* what);

const char* internalFormatName(int internalFormat);

}  // namespace ssam::gl
