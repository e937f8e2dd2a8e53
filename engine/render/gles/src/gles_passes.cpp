// SPDX-License-Identifier: MIT
// GLES driver: a pass's framebuffer, clears, occlusion queries and (CPU) conditional rendering;
// resolves by glBlitFramebuffer; pass times from the CPU clock.
#include <string>
#include <utility>

#include "engine/core/error.hpp"
#include "gl_check.hpp"
#include "gles_driver.hpp"

namespace engine::render::gles {

using gl::checkGl;
using gl::drainGlErrors;

void GlesDriver::beginPass(const DriverPass& pass) {
    const std::string what = "pass " + quotedName(pass.desc->name);
    // The packed colour targets and every attachment's GL name; all have one sample count.
    std::vector<GLuint> colorIds;
    targets_.clear();
    for (NativeId c : pass.color) {
        if (c == kNoNative) continue;
        targets_.push_back(c);
        colorIds.push_back(attachment(textures_[c]));
    }
    const GLuint depthId = pass.depth != kNoNative ? attachment(textures_[pass.depth]) : 0;
    const NativeId any = pass.depth != kNoNative ? pass.depth : targets_.empty() ? kNoNative : targets_.front();
    const int actual = any == kNoNative ? 1 : textures_[any].actualSamples;
    makeCurrent();
    drainGlErrors();
    passStart_ = std::chrono::steady_clock::now();
    const GLuint fbo = framebuffers_.get(colorIds, depthId, what);
    applyBaseState();
    // Clears store the soft backend's bits (fill()).
    for (std::size_t i = 0; i < pass.color.size(); ++i)
        if (pass.color[i] != kNoNative && pass.desc->color[i].load == LoadOp::Clear)
            fill(textures_[pass.color[i]], pass.desc->color[i].clear);
    if (pass.depth != kNoNative && pass.desc->depth.load == LoadOp::Clear)
        fill(textures_[pass.depth], glm::vec4(pass.desc->depth.clear));
    checkGl(what + ": clearing");
    // ES 3.0 has no conditional rendering: the query's result is read here (samplesPassed:
    // waited for natively, as GL_QUERY_WAIT would on the GPU) and the pass's draws are skipped
    // when it counted nothing.
    passSkipped_ = false;
    if (pass.drawOnlyIfSamplesIn != kNoNative) {
        const GLuint condition = queries_[pass.drawOnlyIfSamplesIn].id;
        passSkipped_ = condition && !samplesPassed(condition);
    }
    if (pass.countSamplesInto != kNoNative) {
        GlQuery& q = queries_[pass.countSamplesInto];
        if (!q.id) glGenQueries(1, &q.id);
        glBeginQuery(GL_ANY_SAMPLES_PASSED, q.id);
    }
    pass_ = pass;
    passWidth_ = pass.extent.width, passHeight_ = pass.extent.height, passActualSamples_ = actual;
    passFbo_ = fbo;
}

void GlesDriver::endPass() {
    makeCurrent();
    if (pass_->countSamplesInto != kNoNative) glEndQuery(GL_ANY_SAMPLES_PASSED);
    const std::chrono::duration<double, std::milli> elapsed = std::chrono::steady_clock::now() - passStart_;
    timings_.push_back({pass_->serial, elapsed.count(), passSkipped_});
    pass_.reset();
    targets_.clear();
    checkGl("pass: ending");
}

void GlesDriver::abortPass() noexcept {
    if (!pass_) return;
    try {
        makeCurrent();
        if (pass_->countSamplesInto != kNoNative) glEndQuery(GL_ANY_SAMPLES_PASSED);
    } catch (...) {  // no current context: the pass is dropped all the same
    }
    pass_.reset();
    targets_.clear();
}

std::string GlesDriver::whyNoClosestDepthResolve() const {
    return "OpenGL ES 3.0 cannot read a multisampled depth per sample";
}

// glBlitFramebuffer: a copy between single-sampled textures, the implementation's average of a
// multisampled colour renderbuffer, or one sample of a multisampled depth, the implementation's
// choice (ES 3.0 §4.3.3): DepthResolve::AnySample, the only depth resolve the Device lets
// through here (whyNoClosestDepthResolve), since nothing on ES 3.0 can read the samples.
void GlesDriver::resolve(NativeId source, NativeId destination, const ResolveDesc&, const std::string& what) {
    const GlTexture& src = textures_[source];
    const GlTexture& dst = textures_[destination];
    const bool depth = formatInfo(src.desc.format).isDepth;
    makeCurrent();
    drainGlErrors();
    const GLuint read =
        depth ? framebuffers_.get({}, attachment(src), what) : framebuffers_.get({attachment(src)}, 0, what);
    const GLuint draw =
        depth ? framebuffers_.get({}, attachment(dst), what) : framebuffers_.get({attachment(dst)}, 0, what);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, read);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, draw);
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_RASTERIZER_DISCARD);
    if (!depth) glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    else glDepthMask(GL_TRUE);
    glBlitFramebuffer(0, 0, src.desc.width, src.desc.height, 0, 0, dst.desc.width, dst.desc.height,
                      depth ? GL_DEPTH_BUFFER_BIT : GL_COLOR_BUFFER_BIT, GL_NEAREST);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    checkGl(what);
}

std::vector<DriverTiming> GlesDriver::takeTimings() { return std::exchange(timings_, {}); }

// State every pass and draw relies on; set again each time because a host sharing the
// context may have changed it. ES 3.0 has no GL_MULTISAMPLE or GL_FRAMEBUFFER_SRGB switch:
// both are always on.
void GlesDriver::applyBaseState() {
    // Without the extension the vertex stages do its work (glslEs) under ES's default
    // (lower-left, -1 to 1), which nothing else changes.
    if (extensions_.clipControl) glClipControlEXT(GL_UPPER_LEFT_EXT, GL_ZERO_TO_ONE_EXT);
    glDepthRangef(0.0f, 1.0f);
    glDisable(GL_DITHER);
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_POLYGON_OFFSET_FILL);
    glDisable(GL_RASTERIZER_DISCARD);
    glDisable(GL_SAMPLE_COVERAGE);
    // WebGL2 keeps primitive restart on and refuses the switch (WebGL 2.0 §5.18); the driver's
    // 32-bit indices never reach its 0xFFFFFFFF (a mesh's vertex count is far below that).
#if !defined(__EMSCRIPTEN__)
    glDisable(GL_PRIMITIVE_RESTART_FIXED_INDEX);
#endif
}

}  // namespace engine::render::gles
