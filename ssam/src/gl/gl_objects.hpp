// SPDX-License-Identifier: MIT
#pragma once
// Small GL helpers of ssam::gl: program compilation, texture inspection, framebuffer checks.
// They call GL only through the host's entry points (program building and status names are the
// engine backend's header-only ones, over that table). Errors throw Failure (caught at the
// public API).
#include <initializer_list>
#include <string>

namespace ssam::gl::detail {

struct GlFunctions;

// Compiles and links the sources after shaders::glslHead(gl); Failure(ShaderFailed) naming the
// program and stage with the info log.
unsigned int compileProgram(const GlFunctions& gl, const std::string& name, const char* vertexSource,
                            const char* fragmentSource);

// Where a program's uniform is found: `*location` receives the location of uniform `name` (-1 when
// the program has no such active uniform, which GL's glUniform* then ignores).
struct UniformSlot {
    int* location;
    const char* name;
};
void locateUniforms(const GlFunctions& gl, unsigned int program, std::initializer_list<UniformSlot> slots);

struct TextureInfo {
    int width = 0, height = 0;  // -1: not known (a texture on OpenGL ES 3.0)
    int internalFormat = 0;
};

enum class TextureRole { Color, Depth };

// Level 0 of a GL_TEXTURE_2D; Failure(InvalidTexture) naming `what` when the name is not a
// texture or not a 2D one. Restores the active unit's GL_TEXTURE_2D binding. On OpenGL ES the
// format is read as the `role` attachment of a framebuffer and the size is not known.
TextureInfo inspectTexture2D(const GlFunctions& gl, unsigned int texture, const char* what,
                             TextureRole role = TextureRole::Color);

// A renderbuffer's size and format (the bound renderbuffer is restored); Failure(InvalidTexture)
// naming `what` when the name is not a renderbuffer (saying so when it is a texture's) or is
// multisampled.
TextureInfo inspectRenderbuffer(const GlFunctions& gl, unsigned int renderbuffer, const char* what);

// Failure(IncompleteFramebuffer) naming `what` and the status when the bound draw framebuffer
// is incomplete.
void checkDrawFramebuffer(const GlFunctions& gl, const char* what);

const char* internalFormatName(int internalFormat);

}  // namespace ssam::gl::detail
