// SPDX-License-Identifier: MIT
// Straight-alpha blending in submission order ([Hargreaves 2009] "conventional" over, [Moore 2015]
// "order dependence"): after the opaque resolve, every foliage fragment is blended
// SRC_ALPHA / INV_SRC_ALPHA onto the frame, depth-tested against the opaque depth and
// writing none, so nothing is discarded and the result is exact only where the draws
// happen to arrive back to front. The frame's alpha is not written (it stays 1).
#include "engine/render/owned.hpp"
#include "engine/render/pass_scope.hpp"
#include "foliage_draws.hpp"
#include "single_pass_technique.hpp"
#include "technique_table.hpp"

namespace transparency::detail {

namespace {

using namespace engine::render;

class BlendUnsortedTechnique final : public SinglePassTechnique {
public:
    BlendUnsortedTechnique(Backend& backend, const TechniqueOptions& options)
        : SinglePassTechnique({TechniqueKind::BlendUnsorted}), backend_(backend) {
        pipeline_ = Owned<PipelineHandle>(
            backend_, backend_.createPipeline(blendOverPipeline("foliage blend (unsorted)", options.depthFunc)));
    }

    void drawFrame(engine::render::FrameTargets& opaque, const FoliageFrame& frame,
                   std::span<const engine::render::TextureHandle> /*targets*/) override {
        opaque.resolve();
        const auto visible = visibleDraws(frame, opaque.desc().width, opaque.desc().height);
        if (visible.empty()) return;
        PassScope scope(backend_, resolvedPass(opaque, "foliage blend (unsorted)"));
        for (const FoliageDraw* draw : visible)
            backend_.draw(batchDraw(draw->batch, pipeline_, surfaceParams(frame, draw->batch)));
        scope.end();
    }

private:
    Backend& backend_;
    Owned<PipelineHandle> pipeline_;
};

}  // namespace

std::unique_ptr<Technique> makeBlendUnsortedTechnique(Backend& backend, const TechniqueOptions& options) {
    return std::make_unique<BlendUnsortedTechnique>(backend, options);
}

}  // namespace transparency::detail
