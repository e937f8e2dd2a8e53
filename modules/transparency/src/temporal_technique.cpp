// SPDX-License-Identifier: MIT
// The temporal pass after a technique (transparency/temporal.hpp). Each frame: the technique
// draws as usual (the caller has moved its projection by projectionJitter()), in the same
// frame-graph pass; its frame is
// copied into an RGBA16F `current`, and TemporalResolve writes the blend of current and the
// reprojected, clamped history both into the frame and into the next history target. Draws
// that moved (MaskedBatch::motionVertices) first write their motion into an RGBA16F `motion`
// target (FoliageMotion), which the resolve reprojects those pixels by.
//
// The history is dropped (the frame passes through unchanged) on a cut: FoliageFrame::cut,
// a frame index that does not follow the last one, a new size, or a camera whose matrix does
// not invert.
#include <map>
#include <optional>
#include <string>
#include <utility>

#include "engine/core/error.hpp"
#include "engine/render/owned.hpp"
#include "engine/render/pass_scope.hpp"
#include "foliage_draws.hpp"
#include "technique_table.hpp"
#include "temporal_technique.hpp"
#include "transparency/temporal.hpp"

namespace transparency::detail {

namespace {

using namespace engine::render;

class TemporalTechnique final : public SinglePassTechnique {
public:
    TemporalTechnique(Backend& backend, const TechniqueOptions& options, TechniqueKind kind,
                      std::unique_ptr<SinglePassTechnique> inner)
        : SinglePassTechnique({kind, inner->opaqueSamples(), /*temporal=*/true, options.temporal.jitterPhases,
                               options.temporal.motionVectors}),
          backend_(backend), options_(options.temporal), inner_(std::move(inner)), depthFunc_(options.depthFunc),
          program_(backend, backend.createProgram(temporalResolveProgram())),
          motionProgram_(backend, backend.createProgram(foliageMotionProgram())) {
        if (!(options_.blend > 0.0f && options_.blend <= 1.0f))
            throw engine::Error(std::string(techniqueName(kind)) + ": temporal blend " +
                                std::to_string(options_.blend) + " must be in (0, 1]");
        if (options_.jitterPhases < 1)
            throw engine::Error(std::string(techniqueName(kind)) + ": jitterPhases " +
                                std::to_string(options_.jitterPhases) + " must be >= 1");
        PipelineDesc p;
        p.name = "temporal resolve";
        p.program = program_.get();
        pipeline_ = Owned<PipelineHandle>(backend_, backend_.createPipeline(p));
    }

    // The technique it follows draws through its own targets, in this pass.
    std::vector<TransientTarget> transientTargets(int width, int height, Format colorFormat,
                                                  const FoliageFrame& frame) const override {
        return inner_->transientTargets(width, height, colorFormat, frame);
    }

    void drawFrame(engine::render::FrameTargets& opaque, const FoliageFrame& frame,
                   std::span<const TextureHandle> targets) override {
        inner_->drawFrame(opaque, frame, targets);
        const int width = opaque.desc().width, height = opaque.desc().height;
        const bool sameSize = ensureTargets(width, height, opaque.desc().colorFormat);
        const glm::mat4 unjittered =
            jitteredViewProj(frame.viewProj, -projectionJitter(frame.frameIndex), width, height);
        TemporalResolveParams params;
        params.blend = options_.blend;
        params.hasHistory = hasHistory_ && sameSize && !frame.cut && frame.frameIndex == lastFrame_ + 1 &&
                            reprojectionMatrix(unjittered, previous_, width, height, params.reprojection);
        hasHistory_ = false;  // until this frame's history is written
        MotionReprojection motion;
        if (params.hasHistory && options_.motionVectors &&
            motionReprojection(unjittered, previous_, width, height, motion) && drawMotion(opaque, frame)) {
            params.motion = motion_;
            params.previousToPixels = motion.previousToPixels;
            params.worldW = motion.worldW;
            params.reverseDepth = depthFunc_ == CompareFunc::Greater || depthFunc_ == CompareFunc::GreaterEqual;
        }

        PassDesc copy;
        copy.name = "temporal copy";
        copy.color[0] = {current_, LoadOp::Clear};
        PassScope copyScope(backend_, copy);
        TemporalResolveParams copyParams;
        copyParams.current = opaque.color();
        copyParams.copyOnly = true;
        backend_.draw(fullscreen(copyParams));
        copyScope.end();

        PassDesc resolve;
        resolve.name = "temporal resolve";
        resolve.color[0] = {opaque.color(), LoadOp::Load};
        resolve.color[1] = {history_[1], LoadOp::Clear};
        PassScope resolveScope(backend_, resolve);
        params.current = current_;
        params.depth = opaque.depth();
        params.history = history_[0];
        backend_.draw(fullscreen(params));
        resolveScope.end();

        std::swap(history_[0], history_[1]);
        previous_ = unjittered;
        lastFrame_ = frame.frameIndex;
        hasHistory_ = true;
    }

    std::vector<NamedTarget> intermediates() const override {
        std::vector<NamedTarget> targets = inner_->intermediates();
        if (history_[0].get()) targets.push_back({"taa_history", history_[0].get()});
        return targets;
    }

private:
    // FoliageMotion of every visible draw that moved, and of the opaque draws that moved
    // (FoliageFrame::movingOpaque, their alpha 1), into `motion` (cleared to 0: not written),
    // depth-tested against the depth the technique left without writing it, so that a pixel
    // gets the motion of the nearest moving surface the technique kept there, not of one
    // behind it. Alpha-tested at the material's cutoff: exactly the surfaces alpha testing
    // keeps; hashed keeps some below it, which then follow the camera. False when none moved.
    bool drawMotion(engine::render::FrameTargets& opaque, const FoliageFrame& frame) {
        std::optional<PassScope> scope;
        std::vector<const FoliageDraw*> moved = visibleDraws(frame, width_, height_);
        for (const FoliageDraw& draw : frame.movingOpaque) moved.push_back(&draw);
        for (const FoliageDraw* draw : moved) {
            if (!draw->batch.motionVertices) continue;
            if (!scope) {
                PassDesc pass;
                pass.name = "temporal motion";
                pass.color[0] = {motion_, LoadOp::Clear};
                pass.depth = {opaque.depth(), LoadOp::Load};
                scope.emplace(backend_, pass);
            }
            MaskedBatch motion = draw->batch;
            motion.vertices = motion.motionVertices;
            AlphaOnlyParams params;
            params.viewProj = frame.viewProj;
            params.alphaFactor = motion.baseColorFactor.a;
            params.baseColor = motion.baseColor;
            backend_.draw(batchDraw(motion, motionPipeline(draw->alphaCutoff), params));
        }
        if (!scope) return false;
        scope->end();
        return true;
    }

    // One pipeline per cutoff (materials rarely differ), passing the depth the technique wrote.
    PipelineHandle motionPipeline(float cutoff) {
        if (const auto it = motionPipelines_.find(cutoff); it != motionPipelines_.end()) return it->second;
        PipelineDesc p;
        p.name = "temporal motion";
        p.program = motionProgram_.get();
        const CompareFunc f = depthFunc_ == CompareFunc::Less      ? CompareFunc::LessEqual
                              : depthFunc_ == CompareFunc::Greater ? CompareFunc::GreaterEqual
                                                                   : depthFunc_;
        p.depth = DepthState::testOnly(f);
        p.raster.cull = CullMode::None;
        p.alphaTest = AlphaTest::discardBelow(cutoff);
        Owned<PipelineHandle> pipeline(backend_, backend_.createPipeline(p));
        return motionPipelines_.emplace(cutoff, std::move(pipeline)).first->second;
    }

    DrawDesc fullscreen(const TemporalResolveParams& params) const {
        DrawDesc d;
        d.pipeline = pipeline_;
        d.params = params;
        return d;
    }

    // Whether the targets were already of this size (else they are made anew, history lost).
    // `current` has the frame's format, so that a frame without history passes unchanged;
    // the history is RGBA16F, finer than an 8-bit frame for the small steps of the average.
    bool ensureTargets(int width, int height, Format format) {
        if (current_.get() && width_ == width && height_ == height && format_ == format) return true;
        hasHistory_ = false;
        current_.reset(), history_[0].reset(), history_[1].reset(), motion_.reset();
        width_ = height_ = 0;
        current_ = makeTarget("taa current", width, height, format);
        history_[0] = makeTarget("taa history a", width, height, Format::RGBA16F);
        history_[1] = makeTarget("taa history b", width, height, Format::RGBA16F);
        if (options_.motionVectors) motion_ = makeTarget("taa motion", width, height, Format::RGBA16F);
        width_ = width, height_ = height, format_ = format;
        return false;
    }
    Owned<TextureHandle> makeTarget(const char* name, int width, int height, Format format) {
        return Owned<TextureHandle>(backend_, backend_.createTexture(renderTargetDesc(name, width, height, format)));
    }

    Backend& backend_;
    TemporalOptions options_;
    std::unique_ptr<SinglePassTechnique> inner_;
    CompareFunc depthFunc_;
    Owned<ProgramHandle> program_;
    Owned<ProgramHandle> motionProgram_;
    Owned<PipelineHandle> pipeline_;
    std::map<float, Owned<PipelineHandle>> motionPipelines_;
    Owned<TextureHandle> current_;
    Owned<TextureHandle> history_[2];
    Owned<TextureHandle> motion_;  // RGBA16F world-space motion, alpha > 0 where written
    int width_ = 0, height_ = 0;
    Format format_ = Format::RGBA16F;
    bool hasHistory_ = false;
    std::uint64_t lastFrame_ = 0;
    glm::mat4 previous_{1.0f};
};

}  // namespace

std::unique_ptr<Technique> makeTemporalTechnique(Backend& backend, const TechniqueOptions& options, TechniqueKind kind,
                                                 std::unique_ptr<SinglePassTechnique> inner) {
    return std::make_unique<TemporalTechnique>(backend, options, kind, std::move(inner));
}

}  // namespace transparency::detail
