// SPDX-License-Identifier: MIT
#include "foliage_draws.hpp"

#include "ssam/screen_region.hpp"

namespace transparency::detail {

using namespace engine::render;

std::vector<const FoliageDraw*> visibleDraws(const FoliageFrame& frame, int width, int height) {
    std::vector<const FoliageDraw*> visible;
    for (const FoliageDraw& draw : frame.draws) {
        const ssam::FoliageBatch& b = draw.batch;
        if (b.count == 0 || b.instanceCount == 0) continue;
        if (!ssam::screenRegion(b.worldBounds, frame.viewProj, width, height)) continue;
        visible.push_back(&draw);
    }
    return visible;
}

std::vector<ssam::FoliageBatch> batchesOf(const FoliageFrame& frame) {
    std::vector<ssam::FoliageBatch> batches;
    batches.reserve(frame.draws.size());
    for (const FoliageDraw& draw : frame.draws) batches.push_back(draw.batch);
    return batches;
}

SurfaceParams surfaceParams(const FoliageFrame& frame, const ssam::FoliageBatch& batch) {
    SurfaceParams params;
    params.viewProj = frame.viewProj;
    params.baseColorFactor = batch.baseColorFactor;
    params.baseColor = batch.baseColor;
    params.light = batch.unlit ? unlitLight() : frame.light;
    return params;
}

PipelineDesc foliagePipeline(const char* name) {
    PipelineDesc p;
    p.name = name;
    p.program = ProgramKind::MaskedLit;
    p.raster.cull = CullMode::None;
    return p;
}

PassDesc resolvedPass(const ssam::OpaqueTargets& opaque, const char* name) {
    PassDesc pass;
    pass.name = name;
    pass.color[0] = {opaque.color(), LoadOp::Load};
    pass.depth = {opaque.depth(), LoadOp::Load};
    return pass;
}

DrawDesc batchDraw(const ssam::FoliageBatch& batch, PipelineHandle pipeline, DrawParams params) {
    return ssam::foliageDraw(batch, pipeline, std::move(params));
}

std::vector<NamedTarget> ssamTargets(const ssam::Intermediates& t) {
    std::vector<NamedTarget> out;
    if (t.mask) out.push_back({t.maskAdd ? "mask_max" : "mask", t.mask});
    if (t.maskAdd) out.push_back({"mask_add", t.maskAdd});
    if (t.foliage) out.push_back({"foliage", t.foliage});
    return out;
}

}  // namespace transparency::detail
