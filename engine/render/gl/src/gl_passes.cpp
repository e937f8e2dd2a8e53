// SPDX-License-Identifier: MIT
// GL driver: a pass's framebuffer, clears, timer and occlusion queries and conditional
// rendering; resolves and presenting to a window (readbacks: gl_readback.cpp).
#include <algorithm>
#include <string>
#include <utility>

#include "engine/core/error.hpp"
#include "gl_backend_impl.hpp"
#include "gl_check.hpp"
#include "gl_enums.hpp"
#include "gl_shaders.hpp"

namespace engine::render::gl {

void GlDriverImpl::beginPass(const DriverPass& pass) {
    const std::string& name = pass.desc->name;
    const int width = pass.extent.width, height = pass.extent.height;
    int actual = 1;  // the samples the driver really gave (llvmpipe: 4 for 2)
    std::vector<GLuint> colorIds;
    targets_.clear();
    for (NativeId c : pass.color) {
        if (c == kNoNative) continue;
        const GlTexture& t = textures_[c];
        actual = t.actualSamples;
        colorIds.push_back(t.id);
        targets_.push_back(c);
    }
    GLuint depthId = 0;
    if (pass.depth != kNoNative) {
        const GlTexture& t = textures_[pass.depth];
        actual = t.actualSamples;
        depthId = t.id;
    }

    makeCurrent();
    drainGlErrors();
    const GLuint fbo = framebuffers_.get(colorIds, depthId, "pass " + quotedName(name));

    // The pass's framebuffer is bound, and made known to the driver by a draw that
    // rasterizes nothing, before the query begins: llvmpipe starts the clock of a
    // TIME_ELAPSED query in the tiles of the current framebuffer, and before the first
    // draw into one there are none (the query would report the time since boot).
    applyBaseState();
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glViewport(0, 0, width, height);
    validateFramebufferState();
    glCreateQueries(GL_TIME_ELAPSED, 1, &passQuery_);
    glBeginQuery(GL_TIME_ELAPSED, passQuery_);
    try {
        checkGl("pass " + quotedName(name) + ": starting its timer query");
    } catch (...) {
        glDeleteQueries(1, &passQuery_);
        passQuery_ = 0;
        throw;
    }

    // Clears store the soft backend's bits: the value is encoded here (UNORM rounding,
    // sRGB curve, half rounding to nearest even, depth unclamped) and written with
    // glClearTexImage, which converts nothing; GL's own clear conversion rounds ties to
    // even and halves toward zero on llvmpipe.
    for (std::size_t i = 0; i < pass.color.size(); ++i)
        if (pass.color[i] != kNoNative && pass.desc->color[i].load == LoadOp::Clear)
            clearTexture(textures_[pass.color[i]], pass.desc->color[i].clear);
    if (pass.depth != kNoNative && pass.desc->depth.load == LoadOp::Clear)
        clearTexture(textures_[pass.depth], glm::vec4(pass.desc->depth.clear));
    try {
        checkGl("pass " + quotedName(name) + ": clearing");
    } catch (...) {
        glEndQuery(GL_TIME_ELAPSED);
        glDeleteQueries(1, &passQuery_);
        passQuery_ = 0;
        throw;
    }
    // Queries begin after the clears (glClearTexImage passes no samples and is not
    // conditional anyway): only the pass's draws are counted, or skipped.
    if (pass.countSamplesInto != kNoNative) {
        GlQuery& q = queries_[pass.countSamplesInto];
        // A pending timing still has to read the object's last result: count into a new one.
        if (q.id && conditionPending(q.id)) {
            retiredQueries_.push_back(q.id);
            q.id = 0;
        }
        if (!q.id) {
            glCreateQueries(GL_ANY_SAMPLES_PASSED, 1, &q.id);
            occlusionQueries_.insert(q.id);
        }
        glBeginQuery(GL_ANY_SAMPLES_PASSED, q.id);
    }
    passCondition_ = 0;
    if (pass.drawOnlyIfSamplesIn != kNoNative) {
        passCondition_ = queries_[pass.drawOnlyIfSamplesIn].id;
        glBeginConditionalRender(passCondition_, GL_QUERY_WAIT);
    }
    pass_ = pass;
    passWidth_ = width, passHeight_ = height, passSamples_ = pass.extent.samples, passActualSamples_ = actual;
    passFbo_ = fbo;
}

void GlDriverImpl::endPass() {
    makeCurrent();
    endPassQueries();
    pendingTimings_.push_back({pass_->serial, std::exchange(passQuery_, 0u), std::exchange(passCondition_, 0u)});
    pass_.reset();
    targets_.clear();
    checkGl("pass: ending");
}

// Ends the open pass's conditional rendering, occlusion query and timer query.
void GlDriverImpl::endPassQueries() {
    if (passCondition_) glEndConditionalRender();
    if (pass_->countSamplesInto != kNoNative) glEndQuery(GL_ANY_SAMPLES_PASSED);
    glEndQuery(GL_TIME_ELAPSED);
}

void GlDriverImpl::abortPass() noexcept {
    if (!pass_) return;
    try {
        makeCurrent();
        endPassQueries();
        glDeleteQueries(1, &passQuery_);
    } catch (...) {  // no current context or a destroyed query: the pass is dropped all the same
    }
    passQuery_ = passCondition_ = 0;
    pass_.reset();
    targets_.clear();
}

void GlDriverImpl::resolve(NativeId source, NativeId destination, const ResolveDesc& r, const std::string& what) {
    GlTexture& src = textures_[source];
    GlTexture& dst = textures_[destination];
    makeCurrent();
    drainGlErrors();
    const bool depth = formatInfo(src.desc.format).isDepth;
    if (src.actualSamples == 1) {
        glCopyImageSubData(src.id, GL_TEXTURE_2D, 0, 0, 0, 0, dst.id, GL_TEXTURE_2D, 0, 0, 0, 0, src.desc.width,
                           src.desc.height, 1);
        checkGl(what);
        return;
    }
    ProgramSlot& program = depth ? internalProgram(resolveDepth_, "resolve depth", resolveDepthFragmentSource())
                                 : internalProgram(resolveColor_, "resolve colour", resolveColorFragmentSource());
    const GLuint fbo = depth ? framebuffers_.get({}, dst.id, what) : framebuffers_.get({dst.id}, 0, what);
    applyBaseState();
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glViewport(0, 0, dst.desc.width, dst.desc.height);
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_CULL_FACE);
    glDisable(GL_SAMPLE_ALPHA_TO_COVERAGE);
    glDisablei(GL_BLEND, 0);
    glColorMaski(0, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    if (depth) {
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_ALWAYS);
        glDepthMask(GL_TRUE);
    } else {
        glDisable(GL_DEPTH_TEST);
        glDepthMask(GL_FALSE);
    }
    glUseProgram(program.program.id());
    glProgramUniform1i(program.program.id(), program.program.uniform("u_samples"), src.actualSamples);
    if (depth)
        glProgramUniform1i(program.program.id(), program.program.uniform("u_greater"),
                           isCloser(r.depthFunc, 1.0f, 0.0f) ? 1 : 0);
    glBindTextureUnit(0, src.id);
    glBindSampler(0, 0);
    glBindVertexArray(emptyVao_);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    checkGl(what);
}

std::vector<DriverTiming> GlDriverImpl::takeTimings() {
    std::vector<DriverTiming> out;
    if (pendingTimings_.empty()) return out;
    makeCurrent();
    for (const PendingTiming& p : pendingTimings_) {
        GLuint64 ns = 0;
        glGetQueryObjectui64v(p.query, GL_QUERY_RESULT, &ns);
        glDeleteQueries(1, &p.query);
        GLuint any = 1;
        if (p.condition) glGetQueryObjectuiv(p.condition, GL_QUERY_RESULT, &any);
        out.push_back({p.serial, double(ns) / 1.0e6, any == 0});
    }
    pendingTimings_.clear();
    for (GLuint q : std::exchange(retiredQueries_, {})) releaseQueryObject(q);
    return out;
}

bool GlDriverImpl::present(NativeId h, const TextureDesc&) {
    const GlTexture& t = textures_[h];
    if (!context_ || !context_->hasWindow()) return false;
    const glm::ivec2 size = context_->framebufferSize();
    if (size.x <= 0 || size.y <= 0) return false;  // minimised: nothing to show, nothing to swap
    makeCurrent();
    drainGlErrors();
    GLuint fbo = 0;
    glCreateFramebuffers(1, &fbo);
    glNamedFramebufferTexture(fbo, GL_COLOR_ATTACHMENT0, t.id, 0);
    glNamedFramebufferReadBuffer(fbo, GL_COLOR_ATTACHMENT0);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    // Stored codes are copied as they are (sRGB textures hold display-encoded values).
    glDisable(GL_FRAMEBUFFER_SRGB);
    glDisable(GL_SCISSOR_TEST);
    glColorMaski(0, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    const bool same = size.x == t.desc.width && size.y == t.desc.height;
    // Row 0 at the top of the window: the default framebuffer's row 0 is its bottom.
    glBlitNamedFramebuffer(fbo, 0, 0, 0, t.desc.width, t.desc.height, 0, size.y, size.x, 0, GL_COLOR_BUFFER_BIT,
                           same ? GL_NEAREST : GL_LINEAR);
    glDeleteFramebuffers(1, &fbo);
    glEnable(GL_FRAMEBUFFER_SRGB);
    checkGl("present of " + quotedName(t.desc.name));
    context_->swapBuffers();
    return true;
}

// State every pass, resolve and draw relies on; set again each time because a host
// sharing the context may have changed it.
void GlDriverImpl::applyBaseState() {
    glClipControl(GL_UPPER_LEFT, GL_ZERO_TO_ONE);
    glDepthRange(0.0, 1.0);
    glEnable(GL_FRAMEBUFFER_SRGB);
    glEnable(GL_MULTISAMPLE);
    glDisable(GL_DITHER);
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_POLYGON_OFFSET_FILL);
    glDisable(GL_RASTERIZER_DISCARD);
    glDisable(GL_COLOR_LOGIC_OP);
    glDisable(GL_DEPTH_CLAMP);
    glDisable(GL_SAMPLE_SHADING);
    glDisable(GL_SAMPLE_COVERAGE);
    glDisable(GL_SAMPLE_MASK);
    glDisable(GL_PRIMITIVE_RESTART);
    glDisable(GL_PRIMITIVE_RESTART_FIXED_INDEX);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    glClampColor(GL_CLAMP_READ_COLOR, GL_FALSE);
}

void GlDriverImpl::validateFramebufferState() {
    ProgramSlot& nothing = internalProgram(nothing_, "validate", "#version 450 core\nvoid main() {}\n");
    glUseProgram(nothing.program.id());
    glBindVertexArray(emptyVao_);
    glEnable(GL_RASTERIZER_DISCARD);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glDisable(GL_RASTERIZER_DISCARD);
}

bool GlDriverImpl::conditionPending(GLuint query) const {
    return std::any_of(pendingTimings_.begin(), pendingTimings_.end(),
                       [&](const PendingTiming& p) { return p.condition == query; });
}

// Deleted now, or once the pending timing that reads it is taken.
void GlDriverImpl::releaseQueryObject(GLuint query) {
    if (conditionPending(query)) {
        retiredQueries_.push_back(query);
        return;
    }
    glDeleteQueries(1, &query);
    occlusionQueries_.erase(query);
}

}  // namespace engine::render::gl
