// SPDX-License-Identifier: MIT
#pragma once
// One frame of the engine-hosted SSAM run as the racer runs it (run_graph.hpp): the host's
// colour and depth imported, ssam::addSsamPasses, then "present". SSAM's intermediates are
// the graph's transients; they can be read back before the graph releases them.
#include <algorithm>
#include <string>
#include <vector>

#include "run_graph.hpp"
#include "ssam/frame_graph_passes.hpp"
#include "ssam/ssam.hpp"

namespace test_support {

struct SsamRun {
    // As the frame went: the batches in view and the composite's region (ScreenSpaceAlphaMask::cull),
    // and passesRun, the mask, colour and composite passes the graph ran (0 or 3).
    ssam::FrameReport report;
    std::vector<std::string> passes;  // every pass that ran, "present" last
    // With readIntermediates and foliage in view: rt_mask (or rt_mask_max), rt_mask_add
    // (RG16F precision only, else empty) and rt_foliage as the frame left them.
    engine::render::Readback mask, maskAdd, foliage;
};

// `pool`: as OneFrameGraph's.
inline SsamRun runSsam(ssam::ScreenSpaceAlphaMask& ssam, const ssam::FrameTargets& targets,
                       const ssam::FoliageView& view, bool readIntermediates = false,
                       engine::render::TransientTexturePool* pool = nullptr) {
    OneFrameGraph one(ssam.backend(), pool);
    const ssam::SsamPasses passes =
        ssam::addSsamPasses(one.graph(), ssam, view, one.import(targets.color, targets.depth));
    const std::size_t first = readIntermediates ? one.readBack({passes.mask, passes.maskAdd, passes.foliage}) : 0;
    SsamRun run;
    run.passes = one.run(passes.frame);
    if (readIntermediates)
        run.mask = one.readBacks()[first], run.maskAdd = one.readBacks()[first + 1],
        run.foliage = one.readBacks()[first + 2];

    const engine::render::TextureDesc& color = ssam.backend().describe(targets.color);
    const ssam::FramePlan plan = ssam.cull(color.width, color.height, view);
    run.report.foliageInView = !plan.empty();
    run.report.batchesVisible = int(plan.visible.size());
    run.report.compositeRegion = {plan.compositeRegion.x, plan.compositeRegion.y, plan.compositeRegion.width,
                                  plan.compositeRegion.height};
    for (const char* pass : {"ssam mask", "ssam colour", "ssam composite"})
        run.report.passesRun += int(std::count(run.passes.begin(), run.passes.end(), pass));
    return run;
}

}  // namespace test_support
