// SPDX-License-Identifier: MIT
// Weighted blended order-independent transparency (McGuire & Bavoil, "Weighted Blended
// Order-Independent Transparency", JCGT vol. 2 no. 2, 2013), after the opaque resolve:
//   accumulate  rt_accum (RGBA16F, cleared 0)  += (C * a * w, a * w), ONE/ONE; w is the
//               paper's eq. (7) at the fragment's view depth (program.hpp WboitAccumulate)
//   revealage   rt_reveal (R16F, cleared 1)    *= (1 - a): ZERO / ONE_MINUS_SRC_ALPHA
//   resolve     colour = average * (1 - reveal) + opaque * reveal, with
//               average = accum.rgb / max(accum.a, 1e-5)            (program.hpp WboitResolve)
// Both geometry passes depth-test against the opaque depth and write none. The paper
// writes accumulation and revealage from one pass into two targets (MRT); here every
// program writes one colour to all its targets, so revealage is a second pass with the
// alpha-only program (AlphaOnly, the same alpha MaskedLit computes). The result is
// the same; the cost is a second geometry pass.
#include <cmath>
#include <string>

#include "engine/core/error.hpp"
#include "engine/render/owned.hpp"
#include "engine/render/pass_scope.hpp"
#include "engine/render/screen_bounds.hpp"
#include "foliage_draws.hpp"
#include "single_pass_technique.hpp"
#include "technique_table.hpp"
#include "transparency/programs.hpp"

namespace transparency::detail {

namespace {

using namespace engine::render;

class WboitTechnique final : public SinglePassTechnique {
public:
    WboitTechnique(Backend& backend, const TechniqueOptions& options)
        : SinglePassTechnique({TechniqueKind::Wboit}), backend_(backend), depthScale_(options.wboitDepthScale),
          accumulateProgram_(backend, backend.createProgram(wboitAccumulateProgram())),
          resolveProgram_(backend, backend.createProgram(wboitResolveProgram())) {
        if (!(std::isfinite(depthScale_) && depthScale_ > 0.0f))
            throw engine::Error("wboit: wboitDepthScale " + std::to_string(depthScale_) + " must be finite and > 0");
        PipelineDesc accumulate = foliagePipeline("wboit accumulate");
        accumulate.program = accumulateProgram_.get();
        accumulate.depth = DepthState::testOnly(options.depthFunc);
        accumulate.blend[0] = {true,         BlendFactor::One, BlendFactor::One,
                               BlendOp::Add, BlendFactor::One, BlendFactor::One,
                               BlendOp::Add, WriteAll};
        accumulatePipeline_ = {backend_, backend_.createPipeline(accumulate)};

        PipelineDesc revealage = foliagePipeline("wboit revealage");
        revealage.program = ProgramKind::AlphaOnly;
        revealage.depth = DepthState::testOnly(options.depthFunc);
        revealage.blend[0] = {true,         BlendFactor::Zero, BlendFactor::InvSrcAlpha,
                              BlendOp::Add, BlendFactor::Zero, BlendFactor::InvSrcAlpha,
                              BlendOp::Add, WriteAll};
        revealagePipeline_ = {backend_, backend_.createPipeline(revealage)};

        PipelineDesc resolve;
        resolve.name = "wboit resolve";
        resolve.program = resolveProgram_.get();
        resolve.blend[0] = {true,
                            BlendFactor::InvSrcAlpha,
                            BlendFactor::SrcAlpha,
                            BlendOp::Add,
                            BlendFactor::Zero,
                            BlendFactor::One,
                            BlendOp::Add,
                            WriteRGB};
        resolvePipeline_ = {backend_, backend_.createPipeline(resolve)};
    }

    static constexpr Format kAccumulation = Format::RGBA16F, kRevealage = Format::R16F;

    // The accumulators are the graph's transients.
    std::vector<TransientTarget> transientTargets(int width, int height, Format,
                                                  const FoliageFrame& frame) const override {
        if (visibleDraws(frame, width, height).empty()) return {};
        return {{"wboit_accumulation", renderTargetDesc("rt_wboit_accumulation", width, height, kAccumulation)},
                {"wboit_revealage", renderTargetDesc("rt_wboit_revealage", width, height, kRevealage)}};
    }
    // Into `targets` (accumulation, revealage), which transientTargets() gives whenever foliage is in view.
    void drawFrame(engine::render::FrameTargets& opaque, const FoliageFrame& frame,
                   std::span<const TextureHandle> targets) override {
        opaque.resolve();
        const int width = opaque.desc().width, height = opaque.desc().height;
        const auto visible = visibleDraws(frame, width, height);
        if (visible.empty()) return;
        const TextureHandle accumulation = targets[0], revealage = targets[1];
        const Rect region = screenRegion(visible, frame, width, height);

        drawInto(
            "wboit accumulate", accumulation, glm::vec4(0.0f), opaque, visible, accumulatePipeline_,
            [&](const engine::render::MaskedBatch& b) {
                return WboitAccumulateParams{frame.viewProj, b.baseColorFactor, b.baseColor, frame.light, depthScale_};
            });
        drawInto("wboit revealage", revealage, glm::vec4(1.0f), opaque, visible, revealagePipeline_,
                 [&](const engine::render::MaskedBatch& b) {
                     AlphaOnlyParams params;
                     params.viewProj = frame.viewProj;
                     params.alphaFactor = b.baseColorFactor.a;
                     params.baseColor = b.baseColor;
                     return params;
                 });
        compositeOnto(backend_, opaque, "wboit resolve", resolvePipeline_, WboitResolveParams{accumulation, revealage},
                      region);
    }

private:
    // One pass of every visible draw into `target` (cleared to `clear`), depth-tested against
    // the opaque depth, with the parameters `paramsOf` makes for each batch.
    template <typename ParamsOf>
    void drawInto(const char* name, TextureHandle target, glm::vec4 clear, const engine::render::FrameTargets& opaque,
                  std::span<const FoliageDraw* const> visible, PipelineHandle pipeline, ParamsOf paramsOf) {
        PassDesc pass;
        pass.name = name;
        pass.color[0] = {target, LoadOp::Clear, clear};
        pass.depth = {opaque.depth(), LoadOp::Load};
        PassScope scope(backend_, pass);
        for (const FoliageDraw* draw : visible) backend_.draw(batchDraw(draw->batch, pipeline, paramsOf(draw->batch)));
        scope.end();
    }

    Backend& backend_;
    float depthScale_;
    Owned<ProgramHandle> accumulateProgram_, resolveProgram_;  // programs.hpp
    Owned<PipelineHandle> accumulatePipeline_, revealagePipeline_, resolvePipeline_;
};

}  // namespace

std::unique_ptr<Technique> makeWboitTechnique(Backend& backend, const TechniqueOptions& options) {
    return std::make_unique<WboitTechnique>(backend, options);
}

}  // namespace transparency::detail
