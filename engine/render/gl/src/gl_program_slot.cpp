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

void setUniform(GLuint p, GLint location, const UniformField& field, const std::byte* bytes) {
    const std::byte* at = bytes + field.offset;
    switch (field.type) {
        case UniformType::Float: glProgramUniform1f(p, location, readAt<float>(at)); return;
        case UniformType::Int: glProgramUniform1i(p, location, readAt<int>(at)); return;
        case UniformType::Bool: glProgramUniform1i(p, location, readAt<bool>(at) ? 1 : 0); return;
        case UniformType::Byte: glProgramUniform1i(p, location, int(readAt<std::uint8_t>(at))); return;
        // value_ptr of the value read: the temporary lives until the call returns.
        case UniformType::Vec2: glProgramUniform2fv(p, location, 1, glm::value_ptr(readAt<glm::vec2>(at))); return;
        case UniformType::Vec3: glProgramUniform3fv(p, location, 1, glm::value_ptr(readAt<glm::vec3>(at))); return;
        case UniformType::Direction:  // normalised, as the soft programs normalise it
            glProgramUniform3fv(p, location, 1, glm::value_ptr(glm::normalize(readAt<glm::vec3>(at))));
            return;
        case UniformType::Vec4: glProgramUniform4fv(p, location, 1, glm::value_ptr(readAt<glm::vec4>(at))); return;
        case UniformType::Mat4:
            glProgramUniformMatrix4fv(p, location, 1, GL_FALSE, glm::value_ptr(readAt<glm::mat4>(at)));
            return;
    }
}

}  // namespace

std::shared_ptr<const ProgramSlot> compileSlot(std::shared_ptr<const ProgramDesc> desc, GlslTarget target) {
    auto s = std::make_shared<ProgramSlot>();
    const UniformBlockLayout layout = uniformBlockLayout(desc->name, desc->gl);
    s->program = compileProgram(
        desc->name, withGlslVersion(vertexSource(desc->vertexInput, desc->name, layout), target.major, target.minor),
        withGlslVersion(fragmentSource(desc->vertexInput, layout, desc->gl.fragment), target.major, target.minor));
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
               const NativeTextures& natives, GlSamplerCache& samplers) {
    const GLuint p = s.program.id();
    const auto* bytes = static_cast<const std::byte*>(params.data());
    const GlslProgram& gl = s.desc->gl;
    for (std::size_t i = 0; i < gl.uniforms.size(); ++i) setUniform(p, s.uniforms[i], gl.uniforms[i], bytes);
    for (std::size_t i = 0; i < gl.textures.size(); ++i) {
        const TextureField& field = gl.textures[i];
        const ProgramSlot::TextureUniforms& l = s.textures[i];
        const auto unit = GLuint(field.unit);
        if (field.read == TextureRead::Sampled) {
            const auto binding = readAt<TextureBinding>(bytes + field.offset);
            if (!binding.texture) {
                glProgramUniform1i(p, l.present, 0);
                glBindTextureUnit(unit, 0);
                continue;
            }
            const GlTexture& t = textures[natives.texture(binding.texture)];
            glProgramUniform1i(p, l.present, 1);
            glProgramUniform1i(p, l.filter, int(binding.sampler.filter));
            if (field.premultipliedUniform)
                glProgramUniform1i(p, l.premultiplied, t.desc.alpha == AlphaMode::Premultiplied ? 1 : 0);
            glBindTextureUnit(unit, t.id);
            glBindSampler(unit, samplers.get(binding.sampler));
        } else {
            const auto handle = readAt<TextureHandle>(bytes + field.offset);
            glBindTextureUnit(unit, handle ? textures[natives.texture(handle)].id : 0);
            glBindSampler(unit, 0);
            if (field.presentUniform) glProgramUniform1i(p, l.present, handle ? 1 : 0);
        }
    }
}

}  // namespace engine::render::gl
