// SPDX-License-Identifier: MIT
#include "foliage_draws.hpp"

#include "engine/render/pass_scope.hpp"
#include "engine/render/screen_bounds.hpp"

namespace transparency::detail {

using namespace engine::render;

std::vector<const FoliageDraw*> visibleDraws(const FoliageFrame& frame, int width, int height) {
    std::vector<const FoliageDraw*> visible;
    for (const FoliageDraw& draw : frame.draws) {
        const engine::render::MaskedBatch& b = draw.batch;
        if (b.count == 0 || b.instanceCount == 0) continue;
        if (!engine::render::screenBounds(b.worldBounds, frame.viewProj, width, height)) continue;
        visible.push_back(&draw);
    }
    return visible;
}

Rect screenRegion(std::span<const FoliageDraw* const> visible, const FoliageFrame& frame, int width, int height) {
    Rect region;
    for (const FoliageDraw* draw : visible)
        if (auto r = screenBounds(draw->batch.worldBounds, frame.viewProj, width, height)) region = unite(region, *r);
    return region;
}

std::vector<engine::render::MaskedBatch> batchesOf(const FoliageFrame& frame) {
    std::vector<engine::render::MaskedBatch> batches;
    batches.reserve(frame.draws.size());
    for (const FoliageDraw& draw : frame.draws) batches.push_back(draw.batch);
    return batches;
}

SurfaceParams surfaceParams(const FoliageFrame& frame, const engine::render::MaskedBatch& batch) {
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

PipelineDesc blendOverPipeline(const char* name, CompareFunc depthFunc) {
    PipelineDesc p = foliagePipeline(name);
    p.depth = DepthState::testOnly(depthFunc);
    p.blend[0] = BlendState::alphaOver();
    p.blend[0].writeMask = WriteRGB;
    return p;
}

PassDesc resolvedPass(const engine::render::FrameTargets& opaque, const char* name) {
    PassDesc pass;
    pass.name = name;
    pass.color[0] = {opaque.color(), LoadOp::Load};
    pass.depth = {opaque.depth(), LoadOp::Load};
    return pass;
}

void compositeOnto(Backend& backend, const engine::render::FrameTargets& opaque, const char* name,
                   PipelineHandle pipeline, DrawParams params, const Rect& region) {
    PassDesc pass;
    pass.name = name;
    pass.color[0] = {opaque.color(), LoadOp::Load};
    PassScope scope(backend, pass);
    DrawDesc d;
    d.pipeline = pipeline;
    d.params = std::move(params);
    d.scissor = region;
    backend.draw(d);
    scope.end();
}

DrawDesc batchDraw(const engine::render::MaskedBatch& batch, PipelineHandle pipeline, DrawParams params) {
    return engine::render::maskedBatchDraw(batch, pipeline, params);
}

}  // namespace transparency::detail
