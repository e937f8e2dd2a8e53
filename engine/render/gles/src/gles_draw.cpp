// SPDX-License-Identifier: MIT
// GLES driver: one draw. Its state is resolved by the device (resolved_draw_state.hpp), the
// alpha test's fail modes included as a plan of steps (fail_mode_plan.hpp), as on GL 4.5; what
// ES 3.0 lacks is done per draw: the program's uniforms through the program in use, instances
// from an offset into the instance buffer (no base instance), blending per target only with
// OES_draw_buffers_indexed.
#include <cstdint>
#include <cstring>

#include "engine/core/error.hpp"
#include "engine/render/vertex.hpp"
#include "gl_check.hpp"
#include "gl_enums.hpp"
#include "gl_fixed_function.hpp"
#include "gl_shaders.hpp"
#include "gles_driver.hpp"

namespace engine::render::gles {
namespace {

// ES 3.0 has no glProgramUniform* nor glBindTextureUnit: the draw's program is in use.
const gl::ParamCalls kBoundProgramCalls{
    [](GLuint, GLint l, GLint v) { glUniform1i(l, v); },
    [](GLuint, GLint l, GLfloat v) { glUniform1f(l, v); },
    [](GLuint, GLint l, const GLfloat* v) { glUniform2fv(l, 1, v); },
    [](GLuint, GLint l, const GLfloat* v) { glUniform3fv(l, 1, v); },
    [](GLuint, GLint l, const GLfloat* v) { glUniform4fv(l, 1, v); },
    [](GLuint, GLint l, const GLfloat* v) { glUniformMatrix4fv(l, 1, GL_FALSE, v); },
    [](GLuint unit, GLuint texture) {
        glActiveTexture(GL_TEXTURE0 + unit);
        glBindTexture(GL_TEXTURE_2D, texture);
    },
};

bool sameBlend(const BlendState& a, const BlendState& b) {
    return a.srcRgb == b.srcRgb && a.dstRgb == b.dstRgb && a.srcAlpha == b.srcAlpha && a.dstAlpha == b.dstAlpha &&
           a.opRgb == b.opRgb && a.opAlpha == b.opAlpha;
}

// Names the draw in messages; made only when one is thrown (a string per draw would cost).
std::string drawName(const DriverDraw& draw, const DriverPass& pass) {
    return "draw with pipeline " + quotedName(draw.pipeline->name) + " in pass " + quotedName(pass.desc->name);
}

}  // namespace

// Vertex attributes 0-3 from the vertex buffer, 4-8 from the instance buffer at `firstInstance`
// (what a base instance would select).
void GlesDriver::bindVertices(const DriverDraw& d, std::uint32_t firstInstance) {
    glBindBuffer(GL_ARRAY_BUFFER, buffers_[d.vertices].id);
    auto vertex = [](GLuint location, GLint size, std::size_t offset) {
        glVertexAttribPointer(location, size, GL_FLOAT, GL_FALSE, sizeof(Vertex),
                              reinterpret_cast<const void*>(offset));
    };
    vertex(0, 3, offsetof(Vertex, position));
    vertex(1, 3, offsetof(Vertex, normal));
    vertex(2, 2, offsetof(Vertex, uv));
    vertex(3, 4, offsetof(Vertex, color));
    const bool identity = d.instances == kNoNative;
    glBindBuffer(GL_ARRAY_BUFFER, identity ? identityInstance_ : buffers_[d.instances].id);
    const std::size_t base = identity ? 0 : std::size_t(firstInstance) * sizeof(Instance);
    auto instance = [base](GLuint location, std::size_t offset) {
        glVertexAttribPointer(location, 4, GL_FLOAT, GL_FALSE, sizeof(Instance),
                              reinterpret_cast<const void*>(base + offset));
    };
    for (GLuint c = 0; c < 4; ++c) instance(4 + c, offsetof(Instance, model) + c * sizeof(glm::vec4));
    instance(8, offsetof(Instance, tint));
    glBindBuffer(GL_ARRAY_BUFFER, 0);
}

void GlesDriver::drawRange(const DriverDraw& d, std::uint32_t first, std::uint32_t count, std::uint32_t instances) {
    if (d.indices != kNoNative)
        glDrawElementsInstanced(GL_TRIANGLES, GLsizei(count), GL_UNSIGNED_INT,
                                reinterpret_cast<const void*>(std::uintptr_t(first) * 4), GLsizei(instances));
    else glDrawArraysInstanced(GL_TRIANGLES, GLint(first), GLsizei(count), GLsizei(instances));
}

void GlesDriver::applyBlend(const DriverDraw& draw) {
    const ResolvedDrawState& state = *draw.state;
    bool uniform = true;
    for (std::size_t i = 1; i < targets_.size(); ++i)
        uniform = uniform && state.blendNeeded[i] == state.blendNeeded[0] &&
                  (!state.blendNeeded[0] || sameBlend(state.blend[i], state.blend[0]));
    if (!uniform && !extensions_.drawBuffersIndexed)
        throw Error(drawName(draw, *pass_) +
                    ": different blending per target needs GL_OES_draw_buffers_indexed, which " + renderer_ + " lacks");
    for (std::size_t i = 0; i < targets_.size(); ++i) {
        if (!state.blendNeeded[i]) continue;
        const Format format = textures_[targets_[i]].desc.format;
        if ((format == Format::RGBA32F || format == Format::R32F) && !extensions_.floatBlend)
            throw Error(drawName(draw, *pass_) + ": blending into the " + std::string(formatName(format)) + " target " +
                        quotedName(textures_[targets_[i]].desc.name) + " needs GL_EXT_float_blend, which " + renderer_ +
                        " lacks");
    }
    for (std::size_t i = 0; i < (uniform ? std::min<std::size_t>(targets_.size(), 1) : targets_.size()); ++i) {
        const BlendState& b = state.blend[i];
        const GLuint index = GLuint(i);
        const GLenum srcRgb = gl::glBlendFactor(b.srcRgb), dstRgb = gl::glBlendFactor(b.dstRgb),
                     srcAlpha = gl::glBlendFactor(b.srcAlpha), dstAlpha = gl::glBlendFactor(b.dstAlpha);
        if (uniform) {
            if (!state.blendNeeded[i]) {
                glDisable(GL_BLEND);
                continue;
            }
            glEnable(GL_BLEND);
            glBlendFuncSeparate(srcRgb, dstRgb, srcAlpha, dstAlpha);
            glBlendEquationSeparate(gl::glBlendOp(b.opRgb), gl::glBlendOp(b.opAlpha));
        } else {
            if (!state.blendNeeded[i]) {
                glDisableiOES(GL_BLEND, index);
                continue;
            }
            glEnableiOES(GL_BLEND, index);
            glBlendFuncSeparateiOES(index, srcRgb, dstRgb, srcAlpha, dstAlpha);
            glBlendEquationSeparateiOES(index, gl::glBlendOp(b.opRgb), gl::glBlendOp(b.opAlpha));
        }
    }
    glBlendColor(state.blendConstant.r, state.blendConstant.g, state.blendConstant.b, state.blendConstant.a);
}

// ES 3.0 filters no depth format, and no 32-bit float one without OES_texture_float_linear
// (§3.8.13, Table 3.13): such a texture under a Bilinear or Trilinear sampler is incomplete and
// every read of it returns 0, silently. The draw is refused instead, naming the texture.
void GlesDriver::refuseUnfilterable(const GlesProgram& program, const DriverDraw& draw) {
    const auto* bytes = static_cast<const std::byte*>(draw.desc->params.data());
    for (const TextureField& field : program.slot->desc->gl.textures) {
        if (field.read != TextureRead::Sampled) continue;
        TextureBinding binding;
        std::memcpy(&binding, bytes + field.offset, sizeof binding);
        if (!binding.texture || binding.sampler.filter == Filter::Nearest) continue;
        const TextureDesc& desc = textures_[natives_->texture(binding.texture)].desc;
        const FormatInfo& info = formatInfo(desc.format);
        const bool wide = desc.format == Format::RGBA32F || desc.format == Format::R32F;
        if (!info.isDepth && !(wide && !extensions_.floatLinear)) continue;
        throw Error(drawName(draw, *pass_) + ": " + quotedName(desc.name) + " (" + std::string(info.name) +
                    ") is sampled with a filter, which OpenGL ES 3.0 does not allow for this format" +
                    (info.isDepth ? "" : " without GL_OES_texture_float_linear (" + renderer_ + " lacks it)") +
                    ": its reads would return 0; sample it with Filter::Nearest or read it with texelFetch");
    }
}

// What textureQueryLevels would return for each sampled texture (glslEs).
void GlesDriver::setLevels(const GlesProgram& program, const DrawParams& params) {
    const auto* bytes = static_cast<const std::byte*>(params.data());
    const std::vector<TextureField>& fields = program.slot->desc->gl.textures;
    for (std::size_t i = 0; i < fields.size(); ++i) {
        if (program.levels[i] < 0) continue;
        TextureHandle handle;
        if (fields[i].read == TextureRead::Sampled) {
            TextureBinding binding;
            std::memcpy(&binding, bytes + fields[i].offset, sizeof binding);
            handle = binding.texture;
        } else {
            std::memcpy(&handle, bytes + fields[i].offset, sizeof handle);
        }
        if (handle) glUniform1i(program.levels[i], textures_[natives_->texture(handle)].desc.mipLevels);
    }
}

void GlesDriver::draw(const DriverDraw& draw) {
    if (passSkipped_) return;
    const DrawDesc& d = *draw.desc;
    const PipelineDesc& desc = *draw.pipeline;
    const GlesProgram& program = programs_[draw.program];
    const ProgramSlot& s = *program.slot;
    const bool fullscreen = draw.fullscreen;
    const ResolvedDrawState& state = *draw.state;
    const FailModePlan& plan = state.failModes;
    refuseUnfilterable(program, draw);
    makeCurrent();

    glBindFramebuffer(GL_FRAMEBUFFER, passFbo_);
    glViewport(0, 0, passWidth_, passHeight_);
    glUseProgram(s.program.id());
    glBindVertexArray(fullscreen ? emptyVao_ : vao_);
    gl::setParams(s, d.params, textures_, *natives_, samplers_, kBoundProgramCalls);
    setLevels(program, d.params);

    // The alpha test in the shader; alpha-to-coverage by GL (notePipeline says so).
    glUniform1i(s.alphaFunc, int(desc.alphaTest.func));
    glUniform1f(s.alphaRef, desc.alphaTest.reference);
    if (state.alphaToCoverage) glEnable(GL_SAMPLE_ALPHA_TO_COVERAGE);
    else glDisable(GL_SAMPLE_ALPHA_TO_COVERAGE);
    glUniform1i(s.a2cSamples, 0);
    glUniform1i(s.a2cActual, passActualSamples_);

    // Without EXT_clip_control the vertex stage negates y (glslEs), which reverses every
    // triangle's winding, and the lower-left origin does not negate the facing area back as
    // the upper-left one does: counter-clockwise as displayed is then GL_CW.
    gl::applyDepthAndFaces(desc, state, fullscreen, !extensions_.clipControl);
    const Rect& scissor = state.scissor;
    if (scissor.empty()) return;
    glScissor(scissor.x, scissor.y, scissor.width, scissor.height);  // upper-left origin: y from the top
    if (passActualSamples_ > 1)
        glUniform4i(s.scissor, scissor.x, scissor.y, scissor.x + scissor.width, scissor.y + scissor.height);
    else glUniform4i(s.scissor, 0, 0, 0, 0);
    applyBlend(draw);
    if (!fullscreen) {
        glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, draw.indices != kNoNative ? buffers_[draw.indices].id : 0);
        bindVertices(draw, 0);
    }

    const bool perTarget = extensions_.drawBuffersIndexed;
    auto applyStep = [&](const PlanStep& step) {
        // A step that writes nothing is not drawn, unless an occlusion query counts its samples.
        bool writes = step.depthWrite || pass_->countSamplesInto != kNoNative;
        std::uint8_t first = 0;
        bool sameMask = true;
        for (std::size_t i = 0; i < targets_.size(); ++i) {
            const std::uint8_t m = state.blend[i].writeMask & step.channels;
            writes = writes || m;
            if (i == 0) first = m;
            sameMask = sameMask && m == first;
            if (perTarget)
                glColorMaskiOES(GLuint(i), (m & WriteR) != 0, (m & WriteG) != 0, (m & WriteB) != 0, (m & WriteA) != 0);
        }
        if (!perTarget) {
            if (!sameMask)
                throw Error(drawName(draw, *pass_) +
                            ": different write masks per target need GL_OES_draw_buffers_indexed, which " + renderer_ +
                            " lacks");
            glColorMask((first & WriteR) != 0, (first & WriteG) != 0, (first & WriteB) != 0, (first & WriteA) != 0);
        }
        glDepthMask(step.depthWrite ? GL_TRUE : GL_FALSE);
        glUniform1i(s.alphaSelect, step.select == FragmentSelect::All       ? gl::kSelectAll
                                   : step.select == FragmentSelect::Passing ? gl::kSelectPassing
                                                                            : gl::kSelectFailing);
        return writes;
    };

    if (fullscreen) {
        for (const PlanStep& step : plan.steps)
            if (applyStep(step)) glDrawArrays(GL_TRIANGLES, 0, 3);
    } else if (d.count > 0 && plan.perTriangle) {
        // Triangles in the soft backend's order (instance-major), one instance at a time.
        for (std::uint32_t instance = 0; instance < d.instanceCount; ++instance) {
            bindVertices(draw, instance);
            for (std::uint32_t tri = 0; tri < d.count / 3; ++tri)
                for (const PlanStep& step : plan.steps)
                    if (applyStep(step)) drawRange(draw, d.first + tri * 3, 3, 1);
        }
    } else if (d.count > 0) {
        for (const PlanStep& step : plan.steps)
            if (applyStep(step)) drawRange(draw, d.first, d.count, d.instanceCount);
    }
    if (gl::kCheckEveryDraw) gl::checkGl(drawName(draw, *pass_));
}

}  // namespace engine::render::gles
