// SPDX-License-Identifier: MIT
// SSAM as the paper describes it ([Hathaway 2010]), with options.ssam's knobs: the opaque targets
// are resolved first (SSAM reads the single-sampled rt_opaque and rt_depth, §3.5.1), then
// ssam::ScreenSpaceAlphaMask runs the mask, colour and composite passes (in a frame graph:
// ssam::addSsamPasses, so with no foliage in view they are skipped as empty, and SSAM's
// targets are the graph's transients).
#include "foliage_draws.hpp"
#include "ssam/frame_graph_passes.hpp"
#include "ssam/ssam.hpp"
#include "ssam_targets.hpp"
#include "technique_table.hpp"

namespace transparency::detail {

namespace {

class SsamTechnique final : public Technique {
public:
    SsamTechnique(engine::render::Backend& backend, const TechniqueOptions& options)
        : Technique({TechniqueKind::Ssam}), ssam_(backend, ssamSettings(options)) {}

    engine::render::ColorDepth addPasses(engine::render::FrameGraph& graph, engine::render::FrameTargets& opaque,
                                         const engine::render::ColorDepth& drawn,
                                         const engine::render::ColorDepth& resolved,
                                         const FoliageFrame& frame) override {
        const engine::render::ColorDepth frameTargets = opaque.addResolvePass(graph, drawn, resolved);
        batches_ = batchesOf(frame);
        view_ = {frame.viewProj, frame.light, batches_};
        const ssam::SsamPasses passes = ssam::addSsamPasses(graph, ssam_, view_, frameTargets);
        // The intermediates are the graph's transients; none when the passes are empty.
        graphTargets_.clear();
        if (passes.mask.isValid()) graphTargets_.push_back({maskLayer(passes.maskAdd.isValid()), passes.mask});
        if (passes.maskAdd.isValid()) graphTargets_.push_back({"mask_add", passes.maskAdd});
        if (passes.foliage.isValid()) graphTargets_.push_back({"foliage", passes.foliage});
        return passes.frame;
    }

private:
    ssam::ScreenSpaceAlphaMask ssam_;
    std::vector<engine::render::MaskedBatch> batches_;  // the view's span points here until the graph ran
    ssam::FoliageView view_;                            // the graph's passes read it when they execute
};

}  // namespace

std::unique_ptr<Technique> makeSsamTechnique(engine::render::Backend& backend, const TechniqueOptions& options) {
    return std::make_unique<SsamTechnique>(backend, options);
}

}  // namespace transparency::detail
