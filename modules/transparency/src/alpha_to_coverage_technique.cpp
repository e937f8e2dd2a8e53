// SPDX-License-Identifier: MIT
// Alpha-to-coverage ([Moore 2015]): the opaque pass runs at 4x MSAA (`a2c`; 8x for `a2c8`,
// alpha_to_coverage8_technique.cpp) and the foliage is drawn into those targets with each
// fragment covering round(alpha * 4) of its samples (the engine's deterministic rule,
// AlphaTest::alphaToCoverage), with depth test and write; the resolve then averages the
// samples, so alpha becomes a 5-level (9-level at 8x) coverage fraction.
// Overlapping fragments of equal alpha cover the same samples (no dithering), as in
// hardware with a fixed coverage pattern.
#include <string>

#include "engine/core/error.hpp"
#include "engine/render/owned.hpp"
#include "engine/render/pass_scope.hpp"
#include "alpha_to_coverage_technique.hpp"
#include "foliage_draws.hpp"
#include "single_pass_technique.hpp"
#include "technique_table.hpp"

namespace transparency::detail {

namespace {

using namespace engine::render;

class AlphaToCoverageTechnique final : public SinglePassTechnique {
public:
    AlphaToCoverageTechnique(Backend& backend, const TechniqueOptions& options, TechniqueKind kind, int samples)
        : SinglePassTechnique({kind, samples}), backend_(backend), samples_(samples) {
        PipelineDesc p = foliagePipeline("foliage alpha-to-coverage");
        p.depth = DepthState::testAndWrite(options.depthFunc);
        p.alphaTest.alphaToCoverage = true;
        p.blend[0].writeMask = WriteRGB;  // the frame's alpha stays 1
        pipeline_ = Owned<PipelineHandle>(backend_, backend_.createPipeline(p));
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
            for (const FoliageDraw* draw : visible)
                backend_.draw(batchDraw(draw->batch, pipeline_, surfaceParams(frame, draw->batch)));
            passScope.end();
        }
        opaque.resolve();
    }

private:
    Backend& backend_;
    int samples_;
    Owned<PipelineHandle> pipeline_;
};

}  // namespace

std::unique_ptr<Technique> makeAlphaToCoverageWith(Backend& backend, const TechniqueOptions& options,
                                                   TechniqueKind kind, int samples) {
    return std::make_unique<AlphaToCoverageTechnique>(backend, options, kind, samples);
}

std::unique_ptr<Technique> makeAlphaToCoverageTechnique(Backend& backend, const TechniqueOptions& options) {
    return makeAlphaToCoverageWith(backend, options, TechniqueKind::AlphaToCoverage, 4);
}

}  // namespace transparency::detail
