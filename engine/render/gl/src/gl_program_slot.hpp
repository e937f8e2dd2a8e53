// SPDX-License-Identifier: MIT
#pragma once
// A ProgramDesc compiled for GL: the program object, where its layout's uniforms live, and how
// a draw's parameters (DrawParams, laid out as ProgramDesc::gl says) reach them.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "gl_api.hpp"

#include "engine/render/draw_params.hpp"
#include "engine/render/gl/gl_program.hpp"
#include "engine/render/program_desc.hpp"
#include "gl_caches.hpp"
#include "gl_objects.hpp"

namespace engine::render::gl {

struct ProgramSlot {
    GlProgram program;
    std::shared_ptr<const ProgramDesc> desc;  // null for the backend's internal programs
    std::vector<GLint> uniforms;              // one per desc->gl.uniforms
    struct TextureUniforms {
        GLint present = -1, filter = -1, premultiplied = -1;
    };
    std::vector<TextureUniforms> textures;  // one per desc->gl.textures
    // The shared fragment tail's (finish()).
    GLint alphaSelect = -1, scissor = -1, alphaFunc = -1, alphaRef = -1, a2cSamples = -1, a2cActual = -1;
};

// The GLSL version of the context the sources are compiled for (withGlslVersion).
struct GlslTarget {
    int major = 4, minor = 5;
};

// Compiles a program's GLSL and locates its uniforms.
std::shared_ptr<const ProgramSlot> compileSlot(std::shared_ptr<const ProgramDesc> desc, GlslTarget target);
// The same with the GL 4.5 stages turned into the GLSL a context compiles by `translate` (the
// GLES driver's `#version 300 es` dialect), told which stage (GL_VERTEX_SHADER or
// GL_FRAGMENT_SHADER) each source is: the GLES driver's vertex stages may end differently.
using GlslTranslation = std::function<std::string(std::string source, GLenum stage)>;
std::shared_ptr<const ProgramSlot> compileSlot(std::shared_ptr<const ProgramDesc> desc,
                                               const GlslTranslation& translate);

// One of the backend's own full-screen programs (resolves, the framebuffer check), which have
// no layout: their uniforms are looked up by name.
ProgramSlot compileInternal(const char* name, const std::string& fragment, GlslTarget target);

// How uniforms reach a program and textures their units: GL 4.5 names the program and the unit
// (direct state access); OpenGL ES 3.0 has neither, so its calls set the program in use
// (glUseProgram before setParams) and the active texture unit.
struct ParamCalls {
    void (*uniform1i)(GLuint program, GLint location, GLint value);
    void (*uniform1f)(GLuint program, GLint location, GLfloat value);
    void (*uniform2fv)(GLuint program, GLint location, const GLfloat* value);
    void (*uniform3fv)(GLuint program, GLint location, const GLfloat* value);
    void (*uniform4fv)(GLuint program, GLint location, const GLfloat* value);
    void (*uniformMatrix4fv)(GLuint program, GLint location, const GLfloat* value);
    void (*bindTexture)(GLuint unit, GLuint texture);
};
extern const ParamCalls kDirectStateParamCalls;

// The draw's parameters as the program's layout lays them out: uniforms, and textures bound
// to their units with samplers from `samplers`.
void setParams(const ProgramSlot& slot, const DrawParams& params, const GlTexturePool& textures,
               const NativeTextures& natives, GlSamplerCache& samplers,
               const ParamCalls& calls = kDirectStateParamCalls);

}  // namespace engine::render::gl
