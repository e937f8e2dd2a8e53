// SPDX-License-Identifier: MIT
#include "gl_program_slot.hpp"

#include <cstring>

#include <glm/glm.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "gl_shaders.hpp"

namespace engine::render::gl {
namespace {

void locateTail(ProgramSlot& s) {
    const GlProgram& p = s.program;
    s.alphaSelect = p.uniform("u_alphaSelect");
    s.scissor = p.uniform("u_scissor");
    s.alphaFunc = p.uniform("u_alphaFunc");
    s.alphaRef = p.uniform("u_alphaRef");
    s.a2cSamples = p.uniform("u_a2cSamples");
    s.a2cActual = p.uniform("u_a2cActual");
}

template <typename T>
T readAt(const std::byte* at) {
    T value;
    std::memcpy(&value, at, sizeof value);
    return value;
}

void setUniform(const ParamCalls& c, GLuint p, GLint location, const UniformField& field, const std::byte* bytes) {
    const std::byte* at = bytes + field.offset;
    switch (field.type) {
        case UniformType::Float: c.uniform1f(p, location, readAt<float>(at)); return;
        case UniformType::Int: c.uniform1i(p, location, readAt<int>(at)); return;
        case UniformType::Bool: c.uniform1i(p, location, readAt<bool>(at) ? 1 : 0); return;
        case UniformType::Byte: c.uniform1i(p, location, int(readAt<std::uint8_t>(at))); return;
        // value_ptr of the value read: the temporary lives until the call returns.
        case UniformType::Vec2: c.uniform2fv(p, location, glm::value_ptr(readAt<glm::vec2>(at))); return;
        case UniformType::Vec3: c.uniform3fv(p, location, glm::value_ptr(readAt<glm::vec3>(at))); return;
        case UniformType::Direction:  // normalised, as the soft programs normalise it
            c.uniform3fv(p, location, glm::value_ptr(glm::normalize(readAt<glm::vec3>(at))));
            return;
        case UniformType::Vec4: c.uniform4fv(p, location, glm::value_ptr(readAt<glm::vec4>(at))); return;
        case UniformType::Mat4: c.uniformMatrix4fv(p, location, glm::value_ptr(readAt<glm::mat4>(at))); return;
    }
}

}  // namespace

// GL 4.5's (direct state access). The web page's build has only the GLES driver, whose calls go
// through the program in use (gles_draw.cpp), and WebGL2 has none of these.
#if !defined(__EMSCRIPTEN__)
const ParamCalls kDirectStateParamCalls{
    [](GLuint p, GLint l, GLint v) { glProgramUniform1i(p, l, v); },
    [](GLuint p, GLint l, GLfloat v) { glProgramUniform1f(p, l, v); },
    [](GLuint p, GLint l, const GLfloat* v) { glProgramUniform2fv(p, l, 1, v); },
    [](GLuint p, GLint l, const GLfloat* v) { glProgramUniform3fv(p, l, 1, v); },
    [](GLuint p, GLint l, const GLfloat* v) { glProgramUniform4fv(p, l, 1, v); },
    [](GLuint p, GLint l, const GLfloat* v) { glProgramUniformMatrix4fv(p, l, 1, GL_FALSE, v); },
    [](GLuint unit, GLuint texture) { glBindTextureUnit(unit, texture); },
};
#endif

std::shared_ptr<const ProgramSlot> compileSlot(std::shared_ptr<const ProgramDesc> desc, GlslTarget target) {
    return compileSlot(std::move(desc), [target](std::string source, GLenum) {
        return withGlslVersion(source, target.major, target.minor);
    });
}

std::shared_ptr<const ProgramSlot> compileSlot(std::shared_ptr<const ProgramDesc> desc,
                                               const GlslTranslation& translate) {
    auto s = std::make_shared<ProgramSlot>();
    const UniformBlockLayout layout = uniformBlockLayout(desc->name, desc->gl);
    s->program =
        compileProgram(desc->name, translate(vertexSource(desc->vertexInput, desc->name, layout), GL_VERTEX_SHADER),
                       translate(fragmentSource(desc->vertexInput, layout, desc->gl.fragment), GL_FRAGMENT_SHADER));
    for (const UniformField& u : desc->gl.uniforms) s->uniforms.push_back(s->program.uniform(u.name));
    for (const TextureField& t : desc->gl.textures) {
        ProgramSlot::TextureUniforms& l = s->textures.emplace_back();
        if (t.presentUniform) l.present = s->program.uniform(t.presentUniform);
        if (t.filterUniform) l.filter = s->program.uniform(t.filterUniform);
        if (t.premultipliedUniform) l.premultiplied = s->program.uniform(t.premultipliedUniform);
    }
    locateTail(*s);
    s->desc = std::move(desc);
    return s;
}

ProgramSlot compileInternal(const char* name, const std::string& fragment, GlslTarget target) {
    ProgramSlot s;
    s.program = compileProgram(name, withGlslVersion(fullscreenVertexSource(), target.major, target.minor),
                               withGlslVersion(fragment, target.major, target.minor));
    return s;
}

void setParams(const ProgramSlot& s, const DrawParams& params, const GlTexturePool& textures,
               const NativeTextures& natives, GlSamplerCache& samplers, const ParamCalls& c) {
    const GLuint p = s.program.id();
    const auto* bytes = static_cast<const std::byte*>(params.data());
    const GlslProgram& gl = s.desc->gl;
    for (std::size_t i = 0; i < gl.uniforms.size(); ++i) setUniform(c, p, s.uniforms[i], gl.uniforms[i], bytes);
    for (std::size_t i = 0; i < gl.textures.size(); ++i) {
        const TextureField& field = gl.textures[i];
        const ProgramSlot::TextureUniforms& l = s.textures[i];
        const auto unit = GLuint(field.unit);
        if (field.read == TextureRead::Sampled) {
            const auto binding = readAt<TextureBinding>(bytes + field.offset);
            if (!binding.texture) {
                c.uniform1i(p, l.present, 0);
                c.bindTexture(unit, 0);
                continue;
            }
            const GlTexture& t = textures[natives.texture(binding.texture)];
            c.uniform1i(p, l.present, 1);
            c.uniform1i(p, l.filter, int(binding.sampler.filter));
            if (field.premultipliedUniform)
                c.uniform1i(p, l.premultiplied, t.desc.alpha == AlphaMode::Premultiplied ? 1 : 0);
            c.bindTexture(unit, t.id);
            glBindSampler(unit, samplers.get(binding.sampler));
        } else {
            const auto handle = readAt<TextureHandle>(bytes + field.offset);
            c.bindTexture(unit, handle ? textures[natives.texture(handle)].id : 0);
            glBindSampler(unit, 0);
            if (field.presentUniform) c.uniform1i(p, l.present, handle ? 1 : 0);
        }
    }
}

}  // namespace engine::render::gl
