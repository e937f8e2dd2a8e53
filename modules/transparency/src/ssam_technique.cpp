// SPDX-License-Identifier: MIT
// SSAM as the paper describes it ([Hathaway 2010]), with options.ssam's knobs: the opaque targets
// are resolved first (SSAM reads the single-sampled rt_opaque and rt_depth, §3.5.1), then
// ssam::ScreenSpaceAlphaMask runs the mask, colour and composite passes.
#include "foliage_draws.hpp"
#include "ssam/ssam.hpp"
#include "techniques.hpp"

namespace transparency::detail {

namespace {

class SsamTechnique final : public Technique {
public:
    SsamTechnique(engine::render::Backend& backend, const TechniqueOptions& options)
        : ssam_(backend, options.ssam) {}

    TechniqueKind kind() const override { return TechniqueKind::Ssam; }

    void render(ssam::OpaqueTargets& opaque, const FoliageFrame& frame) override {
        opaque.resolve();
        batches_ = batchesOf(frame);
        ssam_.render({opaque.color(), opaque.depth()}, {frame.viewProj, frame.light, batches_});
    }

    std::vector<NamedTarget> intermediates() const override { return ssamTargets(ssam_.intermediates()); }

private:
    ssam::ScreenSpaceAlphaMask ssam_;
    std::vector<ssam::FoliageBatch> batches_;  // the view's span points here during render
};

}  // namespace

std::unique_ptr<Technique> makeSsamTechnique(engine::render::Backend& backend, const TechniqueOptions& options) {
    return std::make_unique<SsamTechnique>(backend, options);
}

}  // namespace transparency::detail
