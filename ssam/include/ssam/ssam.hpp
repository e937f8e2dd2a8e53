// SPDX-License-Identifier: MIT
#pragma once
// Screen-Space Alpha Masking ([Hathaway 2010], "Alpha Blending as a Post-Process", as shipped in
// Pure). After the engine's opaque pass:
//   1. mask pass    rt_mask    <- foliage alpha only; RGB = MAX, A = ADD, all ONE (Table 3.1);
//                                 depth test against rt_depth, no depth write, no culling,
//                                 nothing rejected by alpha (§3.5.2)
//   2. colour pass  rt_foliage <- foliage colour, alpha-tested at the colour reference, depth
//                                 test and write into rt_depth (foliage depth for later passes),
//                                 no culling, no blending, cleared to the clear colour (§3.5.3)
//   3. composite    colour     <- lerp(colour, foliage, mask'), mask' = lerp(max, add, maskLerp)
//                                 squared (§3.5.4, §3.6.2), scissored to the foliage's bounds.
//   4. depthMaskThreshold > 0: the colour pass draws into a copy of the opaque depth, and the
//      foliage is drawn again, depth only, into rt_depth where the composited mask reaches the
//      threshold (foliage_depth_program.hpp): elsewhere later passes see the opaque depth.
// Depends only on engine/render: works with any Backend, in any engine. A frame runs one way,
// as passes added to the engine's frame graph (ssam/frame_graph_passes.hpp addSsamPasses), whose
// transients are SSAM's intermediate targets.
#include <optional>
#include <vector>

#include "engine/render/backend.hpp"
#include "ssam/composite_program.hpp"
#include "ssam/core/frame.hpp"
#include "ssam/core/passes.hpp"
#include "ssam/core/settings.hpp"
#include "ssam/foliage.hpp"

namespace ssam {

struct FrameTargets {
    engine::render::TextureHandle color;  // the opaque colour; the composite blends onto it
    engine::render::TextureHandle depth;  // D32F opaque depth; receives the foliage depth
};

// What one frame decided: which batches are visible and where the composite runs.
struct FramePlan {
    int width = 0;
    int height = 0;
    std::vector<const engine::render::MaskedBatch*>
        visible;  // in submission order (§3.8: only consistency of order is needed)
    engine::render::Rect compositeRegion;
    bool empty() const { return visible.empty(); }
};

// The intermediate targets, e.g. for captures (the paper's Figures 3.6-3.9).
struct Intermediates {
    engine::render::TextureHandle mask;     // r = MAX mask; a = ADD mask unless maskAdd is set
    engine::render::TextureHandle maskAdd;  // RG16F precision: the ADD mask (r)
    engine::render::TextureHandle foliage;  // rt_foliage
    // depthMaskThreshold > 0: the colour pass's depth (a copy of the opaque depth it draws into),
    // so that the host's depth keeps the foliage only where the mask reaches the threshold.
    engine::render::TextureHandle depthCopy;
};

// What those targets are for a frame: render targets of the frame's size, the mask in the
// configured precision, rt_foliage in the frame colour's format. A frame graph creates them
// as transients (ssam::addSsamPasses).
struct IntermediateDescs {
    engine::render::TextureDesc mask;                      // rt_mask, or rt_mask_max with RG16F
    std::optional<engine::render::TextureDesc> maskAdd;    // rt_mask_add, RG16F precision only
    engine::render::TextureDesc foliage;                   // rt_foliage
    std::optional<engine::render::TextureDesc> depthCopy;  // depthMaskThreshold > 0 only (D32F)
};

// The engine's depth function for a DepthTest and back (none for a function that cannot order
// surfaces: Never, Always, Equal, NotEqual).
engine::render::CompareFunc compareFuncOf(DepthTest test);
std::optional<DepthTest> depthTestOf(engine::render::CompareFunc func);

class ScreenSpaceAlphaMask {
public:
    // Throws engine::Error naming the knob when settingsError(settings) is not empty.
    explicit ScreenSpaceAlphaMask(engine::render::Backend& backend, const Settings& settings = {});
    ~ScreenSpaceAlphaMask();
    ScreenSpaceAlphaMask(const ScreenSpaceAlphaMask&) = delete;
    ScreenSpaceAlphaMask& operator=(const ScreenSpaceAlphaMask&) = delete;

    // Validates (engine::Error on a bad knob) and rebuilds what the change affects.
    void setSettings(const Settings& settings);
    const Settings& settings() const { return settings_; }

    // What the frame graph's passes call (addSsamPasses): the plan, the targets'
    // descriptors, and each pass into `targets` (the graph's transients).
    FramePlan cull(int width, int height, const FoliageView& view) const;
    IntermediateDescs intermediateDescs(int width, int height, engine::render::Format colorFormat) const;
    void maskPass(const FramePlan& plan, const FoliageView& view, engine::render::TextureHandle depth,
                  const Intermediates& targets);
    void colorPass(const FramePlan& plan, const FoliageView& view, engine::render::TextureHandle depth,
                   const Intermediates& targets);
    void compositePass(const FramePlan& plan, engine::render::TextureHandle color, const Intermediates& targets);
    // depthMaskThreshold > 0, after the composite: the foliage depth into `depth` where the
    // composited mask reaches the threshold (nothing to do otherwise).
    void foliageDepthPass(const FramePlan& plan, const FoliageView& view, engine::render::TextureHandle depth,
                          const Intermediates& targets);

    engine::render::Backend& backend() const { return backend_; }

private:
    struct Pipelines {
        engine::render::PipelineHandle mask, color, composite;
        // depthMaskThreshold > 0 only: the foliage depth program and its pipeline.
        engine::render::ProgramHandle foliageDepthProgram;
        engine::render::PipelineHandle foliageDepth;
    };
    // All three for `settings`, or none: a create that throws destroys those made before it.
    Pipelines createPipelines(const Settings& settings);
    void destroy(const Pipelines& pipelines);
    CompositeParams compositeParams(const Intermediates& targets) const;  // the composite's inputs and knobs

    engine::render::Backend& backend_;
    Settings settings_;
    core::PassPlan passes_;                           // describePasses(settings_)
    engine::render::ProgramHandle compositeProgram_;  // composite_program.hpp
    Pipelines pipelines_;
};

}  // namespace ssam
