// SPDX-License-Identifier: MIT
// Alpha-to-coverage ([Moore 2015]): the opaque pass runs at 4x MSAA and the foliage is drawn
// into those targets with each fragment covering round(alpha * 4) of its samples (the
// engine's deterministic rule, AlphaTest::alphaToCoverage), with depth test and write; the
// resolve then averages the samples, so alpha becomes a 5-level coverage fraction.
// Overlapping fragments of equal alpha cover the same samples (no dithering), as in
// hardware with a fixed coverage pattern.
#include <string>

#include "engine/core/error.hpp"
#include "engine/render/owned.hpp"
#include "engine/render/pass_scope.hpp"
#include "foliage_draws.hpp"
#include "technique_table.hpp"

namespace transparency::detail {

namespace {

using namespace engine::render;

constexpr int kSamples = 4;

class AlphaToCoverageTechnique final : public Technique {
public:
    AlphaToCoverageTechnique(Backend& backend, const TechniqueOptions& options) : backend_(backend) {
        PipelineDesc p = foliagePipeline("foliage alpha-to-coverage");
        p.depth = DepthState::testAndWrite(options.ssam.depthFunc);
        p.alphaTest.alphaToCoverage = true;
        p.blend[0].writeMask = WriteRGB;  // the frame's alpha stays 1
        pipeline_ = Owned<PipelineHandle>(backend_, backend_.createPipeline(p));
    }

    TechniqueKind kind() const override { return TechniqueKind::AlphaToCoverage; }
    int opaqueSamples() const override { return kSamples; }

    void render(engine::render::FrameTargets& opaque, const FoliageFrame& frame) override {
        const auto visible = visibleDraws(frame, opaque.desc().width, opaque.desc().height);
        if (!visible.empty()) {
            if (opaque.desc().samples != kSamples)
                throw engine::Error("a2c: the opaque targets have " + std::to_string(opaque.desc().samples) +
                                    " sample(s); draw the opaque pass with opaqueSamples() = 4");
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
    Owned<PipelineHandle> pipeline_;
};

}  // namespace

std::unique_ptr<Technique> makeAlphaToCoverageTechnique(Backend& backend, const TechniqueOptions& options) {
    return std::make_unique<AlphaToCoverageTechnique>(backend, options);
}

}  // namespace transparency::detail
