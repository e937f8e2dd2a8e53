// SPDX-License-Identifier: MIT
// Alpha-to-coverage ([Moore 2015]): the opaque pass runs at 4x MSAA (`a2c`; 8x for `a2c8`,
// alpha_to_coverage8_technique.cpp) and the foliage is drawn into those targets with each
// fragment covering round(alpha * 4) of its samples (the engine's deterministic rule,
// AlphaTest::alphaToCoverage), with depth test and write; the resolve then averages the
// samples, so alpha becomes a 5-level (9-level at 8x) coverage fraction.
// Overlapping fragments of equal alpha cover the same samples (no dithering), as in
// hardware with a fixed coverage pattern. `a2c-sharp` (and `a2c8-sharp`) first sharpen the
// alpha by its screen-space derivative around the alpha test's reference [Golus 2017]
// (transparency/sharpened_coverage.hpp): the same shape as the alpha test, anti-aliased.
#include <optional>
#include <string>

#include "engine/core/error.hpp"
#include "engine/render/owned.hpp"
#include "engine/render/pass_scope.hpp"
#include "alpha_to_coverage_technique.hpp"
#include "foliage_draws.hpp"
#include "single_pass_technique.hpp"
#include "technique_table.hpp"
#include "transparency/sharpened_coverage.hpp"

namespace transparency::detail {

namespace {

using namespace engine::render;

class AlphaToCoverageTechnique final : public SinglePassTechnique {
public:
    AlphaToCoverageTechnique(Backend& backend, const TechniqueOptions& options, TechniqueKind kind, int samples,
                             CoverageAlpha alpha)
        : SinglePassTechnique({kind, samples}), backend_(backend), samples_(samples),
          reference_(options.alphaTestReference) {
        PipelineDesc p = foliagePipeline("foliage alpha-to-coverage");
        if (alpha == CoverageAlpha::Sharpened) {
            if (reference_ && !(*reference_ >= 0.0f && *reference_ <= 1.0f))
                throw engine::Error(std::string(techniqueName(kind)) + ": alphaTestReference " +
                                    std::to_string(*reference_) + " must be in [0, 1]");
            sharpenProgram_ = Owned<ProgramHandle>(backend_, backend_.createProgram(sharpenedCoverageLitProgram()));
            p.program = sharpenProgram_.get();
        }
        p.depth = DepthState::testAndWrite(options.depthFunc);
        p.alphaTest.alphaToCoverage = true;
        p.blend[0].writeMask = WriteRGB;  // the frame's alpha stays 1
        pipeline_ = Owned<PipelineHandle>(backend_, backend_.createPipeline(p));
        desc_ = p;
    }

    void drawFrame(engine::render::FrameTargets& opaque, const FoliageFrame& frame,
                   std::span<const engine::render::TextureHandle> /*targets*/) override {
        const auto visible = visibleDraws(frame, opaque.desc().width, opaque.desc().height);
        if (!visible.empty()) {
            if (opaque.desc().samples != samples_)
                throw engine::Error(
                    std::string(techniqueName(kind())) + ": the opaque targets have " +
                    std::to_string(opaque.desc().samples) +
                    " sample(s); draw the opaque pass with opaqueSamples() = " + std::to_string(samples_));
            PassDesc pass = opaque.loadPassDesc();
            pass.name = "foliage alpha-to-coverage";
            PassScope passScope(backend_, pass);
            for (const FoliageDraw* draw : visible) backend_.draw(drawOf(frame, *draw));
            passScope.end();
        }
        opaque.resolve();
    }

private:
    DrawDesc drawOf(const FoliageFrame& frame, const FoliageDraw& draw) {
        const SurfaceParams s = surfaceParams(frame, draw.batch);
        const LodDither dither = lodDitherOf(draw);
        if (sharpenProgram_.get()) {
            // The reference the alpha test would use: the material's cutoff, or the one for all.
            const SharpenedCoverageParams sharp{
                s.viewProj, s.baseColorFactor, s.baseColor, s.light, reference_.value_or(draw.alphaCutoff), dither};
            return batchDraw(draw.batch, pipeline_, sharp);
        }
        if (dither == LodDither::Off) return batchDraw(draw.batch, pipeline_, s);
        return batchDraw(draw.batch, ditheredPipeline(),
                         DitheredSurfaceParams{s.viewProj, s.baseColorFactor, s.baseColor, s.light, dither});
    }

    // The plain pipeline on DitheredMaskedLit, for crossfading batches: made with the first.
    PipelineHandle ditheredPipeline() {
        if (!ditheredPipeline_.get()) {
            ditheredProgram_ = Owned<ProgramHandle>(backend_, backend_.createProgram(ditheredMaskedLitProgram()));
            PipelineDesc p = desc_;
            p.name = "foliage alpha-to-coverage, crossfade dithered";
            p.program = ditheredProgram_.get();
            ditheredPipeline_ = Owned<PipelineHandle>(backend_, backend_.createPipeline(p));
        }
        return ditheredPipeline_;
    }

    Backend& backend_;
    int samples_;
    std::optional<float> reference_;
    Owned<ProgramHandle> sharpenProgram_;  // null: the plain MaskedLit surface
    Owned<PipelineHandle> pipeline_;
    PipelineDesc desc_;  // pipeline_'s
    Owned<ProgramHandle> ditheredProgram_;
    Owned<PipelineHandle> ditheredPipeline_;
};

}  // namespace

std::unique_ptr<Technique> makeAlphaToCoverageWith(Backend& backend, const TechniqueOptions& options,
                                                   TechniqueKind kind, int samples, CoverageAlpha alpha) {
    return std::make_unique<AlphaToCoverageTechnique>(backend, options, kind, samples, alpha);
}

std::unique_ptr<Technique> makeAlphaToCoverageTechnique(Backend& backend, const TechniqueOptions& options) {
    return makeAlphaToCoverageWith(backend, options, TechniqueKind::AlphaToCoverage, 4, CoverageAlpha::Plain);
}

std::unique_ptr<Technique> makeAlphaToCoverageSharpTechnique(Backend& backend, const TechniqueOptions& options) {
    return makeAlphaToCoverageWith(backend, options, TechniqueKind::AlphaToCoverageSharp, 4, CoverageAlpha::Sharpened);
}

}  // namespace transparency::detail
