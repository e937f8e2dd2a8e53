// SPDX-License-Identifier: MIT
#pragma once
// What the SSAM, SSAM+ and SSAM+TAA adapters share: their settings, SSAM's targets as the racer
// names its layers, and SSAM's mask and colour passes inside a technique's single pass.
#include <span>
#include <string>
#include <vector>

#include "engine/core/error.hpp"
#include "engine/render/frame_targets.hpp"
#include "foliage_draws.hpp"
#include "ssam/ssam.hpp"
#include "single_pass_technique.hpp"
#include "transparency/create_technique.hpp"

namespace transparency::detail {

// The layer names: mask (or mask_max + mask_add), foliage.
// ssamSettings(options) for a technique built on SSAM's passes that has no use for its depth
// restore (depthMaskThreshold, tested against SSAM's own composited mask): a threshold above 0 is
// refused, naming the technique and `why`.
inline ssam::Settings ssamSettingsWithoutDepthRestore(const TechniqueOptions& options, const char* technique,
                                                      const char* why) {
    ssam::Settings settings = ssamSettings(options);
    if (settings.depthMaskThreshold > 0.0f)
        throw engine::Error(std::string(technique) + ": depthMaskThreshold = " +
                            std::to_string(settings.depthMaskThreshold) + " " + why + ": use 0");
    return settings;
}

inline const char* maskLayer(bool separateAdd) { return separateAdd ? "mask_max" : "mask"; }

// SSAM's targets as transients of a frame graph, in the order of ssam::Intermediates.
inline std::vector<TransientTarget> ssamTransients(const ssam::IntermediateDescs& d) {
    std::vector<TransientTarget> out{{maskLayer(d.maskAdd.has_value()), d.mask}};
    if (d.maskAdd) out.push_back({"mask_add", *d.maskAdd});
    out.push_back({"foliage", d.foliage});
    return out;
}

// SSAM's targets for `frame` as a single-pass technique's transients; none without foliage in view.
inline std::vector<TransientTarget> ssamFrameTransients(const ssam::ScreenSpaceAlphaMask& ssam, int width, int height,
                                                        engine::render::Format colorFormat, const FoliageFrame& frame) {
    const std::vector<engine::render::MaskedBatch> batches = batchesOf(frame);
    if (ssam.cull(width, height, {frame.viewProj, frame.light, batches}).empty()) return {};
    return ssamTransients(ssam.intermediateDescs(width, height, colorFormat));
}

// The opaque targets resolved (§3.5.1), then SSAM's mask and colour passes into `targets`
// (ssamFrameTransients' order; `batches` keeps the frame's batches). The plan is empty, and
// nothing drawn, without foliage in view.
struct SsamLayers {
    ssam::FramePlan plan;
    ssam::Intermediates targets;
};
inline SsamLayers drawSsamLayers(engine::render::Backend& backend, ssam::ScreenSpaceAlphaMask& ssam,
                                 engine::render::FrameTargets& opaque, const FoliageFrame& frame,
                                 std::span<const engine::render::TextureHandle> targets,
                                 std::vector<engine::render::MaskedBatch>& batches) {
    opaque.resolve();
    if (targets.empty()) return {};
    batches = batchesOf(frame);
    const ssam::FoliageView view{frame.viewProj, frame.light, batches};
    const engine::render::TextureDesc& color = backend.describe(opaque.color());
    SsamLayers layers{ssam.cull(color.width, color.height, view), {}};
    if (layers.plan.empty()) return layers;
    const bool separateAdd = targets.size() == 3;
    layers.targets = {targets[0], separateAdd ? targets[1] : engine::render::TextureHandle{}, targets.back(), {}};
    ssam.maskPass(layers.plan, view, opaque.depth(), layers.targets);
    ssam.colorPass(layers.plan, view, opaque.depth(), layers.targets);
    return layers;
}

}  // namespace transparency::detail
