// SPDX-License-Identifier: MIT
// GL driver: one draw. Its state is resolved by the device (resolved_draw_state.hpp),
// the alpha test's fail modes included as a plan of steps (fail_mode_plan.hpp); here each step
// is issued with the channels and depth it may write.
#include <algorithm>
#include <array>
#include <cstdint>

#include "engine/core/error.hpp"
#include "engine/render/vertex.hpp"
#include "gl_backend_impl.hpp"
#include "gl_check.hpp"
#include "gl_enums.hpp"
#include "gl_fixed_function.hpp"
#include "gl_shaders.hpp"

namespace engine::render::gl {

void GlDriverImpl::drawRange(const DriverDraw& d, std::uint32_t first, std::uint32_t count, std::uint32_t baseInstance,
                             std::uint32_t instances) {
    if (d.indices != kNoNative)
        glDrawElementsInstancedBaseInstance(GL_TRIANGLES, GLsizei(count), GL_UNSIGNED_INT,
                                            reinterpret_cast<const void*>(std::uintptr_t(first) * 4),
                                            GLsizei(instances), baseInstance);
    else
        glDrawArraysInstancedBaseInstance(GL_TRIANGLES, GLint(first), GLsizei(count), GLsizei(instances), baseInstance);
}

// Exact fail modes: a triangle's fragments never overlap, so its passing and failing steps
// commute; triangles go in the soft backend's order (instance-major).
template <typename ApplyStep>
void GlDriverImpl::drawPerTriangle(const DriverDraw& d, const FailModePlan& plan, ApplyStep& applyStep) {
    for (std::uint32_t instance = 0; instance < d.desc->instanceCount; ++instance)
        for (std::uint32_t tri = 0; tri < d.desc->count / 3; ++tri)
            for (const PlanStep& step : plan.steps)
                if (applyStep(step)) drawRange(d, d.desc->first + tri * 3, 3, instance, 1);
}

void GlDriverImpl::draw(const DriverDraw& draw) {
    const DrawDesc& d = *draw.desc;
    const PipelineDesc& desc = *draw.pipeline;
    const ProgramSlot& s = *programs_[draw.program];
    const bool fullscreen = draw.fullscreen;
    const GLuint p = s.program.id();
    const ResolvedDrawState& state = *draw.state;
    const FailModePlan& plan = state.failModes;
    makeCurrent();

    // The base state was applied when the pass began; within a pass only this backend
    // touches the context (a host sharing it changes state between passes, not inside one).
    glBindFramebuffer(GL_FRAMEBUFFER, passFbo_);
    glViewport(0, 0, passWidth_, passHeight_);
    glUseProgram(p);
    glBindVertexArray(fullscreen ? emptyVao_ : vao_);
    setParams(s, d.params, textures_, *natives_, samplers_);

    // Alpha test and alpha-to-coverage uniforms.
    glProgramUniform1i(p, s.alphaFunc, int(desc.alphaTest.func));
    glProgramUniform1f(p, s.alphaRef, desc.alphaTest.reference);
    const bool a2c = state.alphaToCoverage;
    if (a2c && options_.nativeAlphaToCoverage) glEnable(GL_SAMPLE_ALPHA_TO_COVERAGE);
    else glDisable(GL_SAMPLE_ALPHA_TO_COVERAGE);
    const bool shaderA2c = a2c && !options_.nativeAlphaToCoverage;
    glProgramUniform1i(p, s.a2cSamples, shaderA2c ? passSamples_ : 0);
    glProgramUniform1i(p, s.a2cActual, passActualSamples_);

    // Depth, culling, scissor.
    applyDepthAndFaces(desc, state, fullscreen);
    const Rect& scissor = state.scissor;
    if (scissor.empty()) return;
    glScissor(scissor.x, scissor.y, scissor.width, scissor.height);  // upper-left origin: y from the top
    if (passActualSamples_ > 1)
        glProgramUniform4i(p, s.scissor, scissor.x, scissor.y, scissor.x + scissor.width, scissor.y + scissor.height);
    else glProgramUniform4i(p, s.scissor, 0, 0, 0, 0);

    // Blending per target.
    for (std::size_t i = 0; i < targets_.size(); ++i) {
        const BlendState& b = state.blend[i];
        if (!state.blendNeeded[i]) {
            glDisablei(GL_BLEND, GLuint(i));
            continue;
        }
        glEnablei(GL_BLEND, GLuint(i));
        glBlendFuncSeparatei(GLuint(i), glBlendFactor(b.srcRgb), glBlendFactor(b.dstRgb), glBlendFactor(b.srcAlpha),
                             glBlendFactor(b.dstAlpha));
        glBlendEquationSeparatei(GLuint(i), glBlendOp(b.opRgb), glBlendOp(b.opAlpha));
    }
    glBlendColor(state.blendConstant.r, state.blendConstant.g, state.blendConstant.b, state.blendConstant.a);

    // Vertex input.
    if (!fullscreen) {
        glVertexArrayVertexBuffer(vao_, 0, buffers_[draw.vertices].id, 0, sizeof(Vertex));
        glVertexArrayVertexBuffer(vao_, 1,
                                  draw.instances != kNoNative ? buffers_[draw.instances].id : identityInstance_, 0,
                                  sizeof(Instance));
        glVertexArrayElementBuffer(vao_, draw.indices != kNoNative ? buffers_[draw.indices].id : 0);
    }

    auto applyStep = [&](const PlanStep& step) {
        // A step that writes nothing is not drawn, unless an occlusion query counts its samples.
        bool writes = step.depthWrite || pass_->countSamplesInto != kNoNative;
        for (std::size_t i = 0; i < targets_.size(); ++i) {
            const std::uint8_t m = state.blend[i].writeMask & step.channels;
            writes = writes || m;
            glColorMaski(GLuint(i), (m & WriteR) != 0, (m & WriteG) != 0, (m & WriteB) != 0, (m & WriteA) != 0);
        }
        glDepthMask(step.depthWrite ? GL_TRUE : GL_FALSE);
        glProgramUniform1i(p, s.alphaSelect,
                           step.select == FragmentSelect::All       ? kSelectAll
                           : step.select == FragmentSelect::Passing ? kSelectPassing
                                                                    : kSelectFailing);
        return writes;
    };

    if (fullscreen) {
        for (const PlanStep& step : plan.steps)
            if (applyStep(step)) glDrawArrays(GL_TRIANGLES, 0, 3);
    } else if (d.count > 0) {
        if (plan.perTriangle) drawPerTriangle(draw, plan, applyStep);
        else
            for (const PlanStep& step : plan.steps)
                if (applyStep(step)) drawRange(draw, d.first, d.count, 0, d.instanceCount);
    }
    // glGetError stalls a threaded driver and the message costs a string per draw: errors
    // are checked per draw only in debug builds or with debug output on, and always at the
    // end of the pass (endPass), which names the pass.
    if (kCheckEveryDraw || options_.debugOutput)
        checkGl("draw with pipeline " + quotedName(desc.name) + " in pass " + quotedName(pass_->desc->name));
}

}  // namespace engine::render::gl
