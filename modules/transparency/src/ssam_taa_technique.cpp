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

// The restore needs a depth copy among the targets; the temporal pass reads the depth SSAM left.
ssam::Settings taaSettings(const TechniqueOptions& options) {
    return ssamSettingsWithoutDepthRestore(options, "ssam+taa", "is not supported under the temporal pass");
}

// SSAM's three passes as one frame-graph pass's work, so that the temporal pass can run it.
class SsamFramePass final : public SinglePassTechnique {
public:
    SsamFramePass(Backend& backend, const TechniqueOptions& options)
        : SinglePassTechnique({TechniqueKind::Ssam}), backend_(backend), ssam_(backend, taaSettings(options)) {}

    std::vector<TransientTarget> transientTargets(int width, int height, Format colorFormat,
                                                  const FoliageFrame& frame) const override {
        return ssamFrameTransients(ssam_, width, height, colorFormat, frame);
    }

    void drawFrame(FrameTargets& opaque, const FoliageFrame& frame, std::span<const TextureHandle> targets) override {
        const SsamLayers layers = drawSsamLayers(backend_, ssam_, opaque, frame, targets, batches_);
        if (!layers.plan.empty()) ssam_.compositePass(layers.plan, opaque.color(), layers.targets);
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
