// SPDX-License-Identifier: MIT
// `ssam+taa`: SSAM ([Hathaway 2010] §3.5, options.ssam's knobs) drawn under the temporal pass's
// jitter, then the temporal pass (transparency/temporal.hpp, temporal_technique.cpp): the
// history averages the colour pass's alpha-tested front layer over the jitter, which is where
// SSAM's remaining flicker comes from (ssam/docs/steady_in_motion.md), while SSAM's mask
// already gives every frame the partial coverage a TAA'd alpha test has to accumulate.
#include <string>

#include "engine/core/error.hpp"
#include "foliage_draws.hpp"
#include "ssam/ssam.hpp"
#include "ssam_targets.hpp"
#include "technique_table.hpp"
#include "temporal_technique.hpp"

namespace transparency::detail {

namespace {

using namespace engine::render;

ssam::Settings taaSettings(const TechniqueOptions& options) {
    ssam::Settings settings = ssamSettings(options);
    // The restore needs a depth copy among the targets; the temporal pass reads the depth SSAM left.
    if (settings.depthMaskThreshold > 0.0f)
        throw engine::Error("ssam+taa: depthMaskThreshold = " + std::to_string(settings.depthMaskThreshold) +
                            " is not supported under the temporal pass: use 0");
    return settings;
}

// SSAM's three passes as one frame-graph pass's work, so that the temporal pass can run it.
class SsamFramePass final : public SinglePassTechnique {
public:
    SsamFramePass(Backend& backend, const TechniqueOptions& options)
        : SinglePassTechnique({TechniqueKind::Ssam}), backend_(backend), ssam_(backend, taaSettings(options)) {}

    std::vector<TransientTarget> transientTargets(int width, int height, Format colorFormat,
                                                  const FoliageFrame& frame) const override {
        const std::vector<MaskedBatch> batches = batchesOf(frame);
        if (ssam_.cull(width, height, {frame.viewProj, frame.light, batches}).empty()) return {};
        return ssamTransients(ssam_.intermediateDescs(width, height, colorFormat));
    }

    void drawFrame(FrameTargets& opaque, const FoliageFrame& frame, std::span<const TextureHandle> targets) override {
        opaque.resolve();
        if (targets.empty()) return;
        batches_ = batchesOf(frame);
        const ssam::FoliageView view{frame.viewProj, frame.light, batches_};
        const TextureDesc& color = backend_.describe(opaque.color());
        const ssam::FramePlan plan = ssam_.cull(color.width, color.height, view);
        if (plan.empty()) return;
        const bool separateAdd = targets.size() == 3;
        const ssam::Intermediates t{targets[0], separateAdd ? targets[1] : TextureHandle{}, targets.back(), {}};
        ssam_.maskPass(plan, view, opaque.depth(), t);
        ssam_.colorPass(plan, view, opaque.depth(), t);
        ssam_.compositePass(plan, opaque.color(), t);
    }

private:
    Backend& backend_;
    ssam::ScreenSpaceAlphaMask ssam_;
    std::vector<MaskedBatch> batches_;
};

}  // namespace

std::unique_ptr<Technique> makeSsamTaaTechnique(Backend& backend, const TechniqueOptions& options) {
    return makeTemporalTechnique(backend, options, TechniqueKind::SsamTaa,
                                 std::make_unique<SsamFramePass>(backend, options));
}

}  // namespace transparency::detail
