// SPDX-License-Identifier: MIT
// SSAM+ (README "SSAM+"): SSAM's mask pass and colour pass unchanged ([Hathaway 2010] §3.5.2,
// §3.5.3, run by ssam::ScreenSpaceAlphaMask), with two changes measured against the exact
// reference (modules/transparency README / report):
//   - the mask is stored in floats (two R16F targets by default: the memory of one RGBA8
//     mask plus one, and the same error as RGBA16F), so the ADD mask keeps counting past 1
//     instead of saturating;
//   - the composite estimates the pixel's covered fraction 1 - prod(1 - a_i) from the two
//     masks (programs.hpp CoverageModel; by default n = ADD / MAX layers of alpha MAX:
//     1 - (1 - MAX)^(ADD / MAX)) where the paper uses lerp(MAX, ADD, 0.85) squared, a
//     hand-tuned stand-in for the same quantity (§3.5.4, §3.6.2);
//   - by default the composite averages the foliage colour over 3x3 (programs.hpp
//     CoverageBlurComposite): the colour pass keeps one layer per pixel, the average stands
//     in for the blend of several (ssam/docs/ssam_plus.md has what each idea tried gave);
//   - by default a front-layers pass after the colour pass draws every foliage layer again,
//     depth-tested against the depth the colour pass wrote (not writing it), adding (a * C, a)
//     into an RGBA16F target: the layers in front of the kept leaf, which the alpha test
//     dropped, and every layer where no leaf was kept. The composite takes the kept leaf's colour
//     over their mean by the kept leaf's alpha (programs.hpp CoverageCompositeParams::frontLayers).
// The composite does a pow() and 9 colour reads per pixel more than SSAM's; the front layers
// cost a third geometry pass (most of its fragments fail the depth test) and 8 bytes a pixel.
#include <string>

#include "engine/core/error.hpp"
#include "engine/render/owned.hpp"
#include "engine/render/pass_scope.hpp"
#include "foliage_draws.hpp"
#include "ssam/ssam.hpp"
#include "ssam_targets.hpp"
#include "single_pass_technique.hpp"
#include "technique_table.hpp"
#include "transparency/programs.hpp"

namespace transparency::detail {

namespace {

using namespace engine::render;

ssam::Settings plusSettings(const TechniqueOptions& options) {
    // The threshold is tested against SSAM's composited mask; SSAM+'s coverage composite has another.
    ssam::Settings settings = ssamSettingsWithoutDepthRestore(
        options, "ssam-plus", "is SSAM's (its mask); SSAM+'s coverage composite has none");
    settings.maskPrecision = options.ssamPlus.maskPrecision;
    settings.colorAlphaReference = options.ssamPlus.colorAlphaReference;
    settings.squareMask = false;  // not used by the coverage composite
    return settings;
}

class SsamPlusTechnique final : public SinglePassTechnique {
public:
    SsamPlusTechnique(Backend& backend, const TechniqueOptions& options)
        : SinglePassTechnique({TechniqueKind::SsamPlus}), backend_(backend), ssam_(backend, plusSettings(options)),
          model_(options.ssamPlus.coverage) {
        if (model_ != CoverageModel::EqualLayers && model_ != CoverageModel::Exponential)
            throw engine::Error("ssam-plus: unknown coverage model " + std::to_string(int(model_)));
        PipelineDesc composite;
        composite.name = "ssam+ composite";
        program_ = {backend_, backend_.createProgram(options.ssamPlus.compositeBlur ? coverageBlurCompositeProgram()
                                                                                    : coverageCompositeProgram())};
        composite.program = program_.get();
        composite.blend[0] = BlendState::alphaOverKeepAlpha();  // as SSAM's composite
        composite_ = {backend_, backend_.createPipeline(composite)};
        if (options.ssamPlus.frontLayers) {
            PipelineDesc front = foliagePipeline("ssam+ front layers");
            front.depth = DepthState::testOnly(options.depthFunc);
            // A fragment of alpha 0 adds nothing: dropped before it is lit (the soft backend's
            // alpha-first rows; 56 -> 47 ms in the forest at 1280x720), the sums unchanged.
            front.alphaTest = {true, CompareFunc::Greater, 0.0f, AlphaFailMode::Keep, false};
            // rgb += C * a, a += a: the layers' colours weighted by their alphas, and the weights.
            front.blend[0] = {true,
                              BlendFactor::SrcAlpha,
                              BlendFactor::One,
                              BlendOp::Add,
                              BlendFactor::One,
                              BlendFactor::One,
                              BlendOp::Add,
                              WriteAll};
            frontLayers_ = {backend_, backend_.createPipeline(front)};
        }
    }

    static constexpr Format kFrontLayers = Format::RGBA16F;

    // SSAM's targets are the graph's transients, made only when foliage is in view.
    std::vector<TransientTarget> transientTargets(int width, int height, Format colorFormat,
                                                  const FoliageFrame& frame) const override {
        std::vector<TransientTarget> targets = ssamFrameTransients(ssam_, width, height, colorFormat, frame);
        if (frontLayers_.get() && !targets.empty())
            targets.push_back({"front_layers", renderTargetDesc("rt_front_layers", width, height, kFrontLayers)});
        return targets;
    }
    // Into `targets` (ssamTransients' order, then the front layers'); none when no foliage is in view.
    void drawFrame(engine::render::FrameTargets& opaque, const FoliageFrame& frame,
                   std::span<const TextureHandle> targets) override {
        const std::size_t ssamTargets = frontLayers_.get() && !targets.empty() ? targets.size() - 1 : targets.size();
        const SsamLayers layers = drawSsamLayers(backend_, ssam_, opaque, frame, targets.first(ssamTargets), batches_);
        if (layers.plan.empty()) return;
        const ssam::Intermediates& t = layers.targets;
        const ssam::FramePlan& plan = layers.plan;
        CoverageCompositeParams params{t.foliage, t.mask, t.maskAdd, model_};
        if (frontLayers_.get()) {
            params.frontLayers = targets.back();
            drawFrontLayers(opaque, frame, plan, params.frontLayers);
        }
        compositeOnto(backend_, opaque, "ssam+ composite", composite_, params, plan.compositeRegion);
    }

private:
    // The plan's batches again into `target` (cleared to 0), depth-tested against the opaque depth
    // the colour pass has since written its kept leaves into.
    void drawFrontLayers(const engine::render::FrameTargets& opaque, const FoliageFrame& frame,
                         const ssam::FramePlan& plan, TextureHandle target) {
        PassDesc pass;
        pass.name = "ssam+ front layers";
        pass.color[0] = {target, LoadOp::Clear, glm::vec4(0.0f)};
        pass.depth = {opaque.depth(), LoadOp::Load};
        PassScope scope(backend_, pass);
        for (const engine::render::MaskedBatch* batch : plan.visible)
            backend_.draw(batchDraw(*batch, frontLayers_.get(), surfaceParams(frame, *batch)));
        scope.end();
    }

    Backend& backend_;
    ssam::ScreenSpaceAlphaMask ssam_;
    CoverageModel model_;
    Owned<ProgramHandle> program_;  // programs.hpp coverage(Blur)CompositeProgram
    Owned<PipelineHandle> composite_;
    Owned<PipelineHandle> frontLayers_;  // SsamPlusOptions::frontLayers: the front-layers pass
    std::vector<engine::render::MaskedBatch> batches_;
};

}  // namespace

std::unique_ptr<Technique> makeSsamPlusTechnique(Backend& backend, const TechniqueOptions& options) {
    return std::make_unique<SsamPlusTechnique>(backend, options);
}

}  // namespace transparency::detail
