// SPDX-License-Identifier: MIT
#include "ssam/ssam.hpp"

#include "engine/render/pass_scope.hpp"
#include "ssam/composite_program.hpp"
#include "engine/render/screen_bounds.hpp"

namespace ssam {

using namespace engine::render;

namespace {

// Mask pass (§3.5.2, Table 3.1): RGB = MAX and A = ADD with ONE/ONE, depth test without
// write, both faces, no alpha rejection (the paper's alpha reference of 0).
PipelineDesc maskPipelineDesc(const Config& config) {
    PipelineDesc mask;
    mask.name = "ssam mask";
    mask.program = ProgramKind::AlphaOnly;
    mask.depth = DepthState::testOnly(config.depthFunc);
    mask.raster.cull = CullMode::None;
    if (config.maskPrecision == MaskPrecision::RG16F) {
        // Two R16F targets, one blend equation each.
        mask.blend[0] = BlendState::oneOne(BlendOp::Max, BlendOp::Max);
        mask.blend[1] = BlendState::oneOne(BlendOp::Add, BlendOp::Add);
    } else {
        mask.blend[0] = BlendState::maxRgbAddAlpha();
    }
    return mask;
}

// Colour pass (§3.5.3): alpha test at the colour reference, depth test and write, no
// culling, no blending.
PipelineDesc colorPipelineDesc(const Config& config) {
    PipelineDesc color;
    color.name = "ssam colour";
    color.program = ProgramKind::MaskedLit;
    color.depth = DepthState::testAndWrite(config.depthFunc);
    color.raster.cull = CullMode::None;
    color.alphaTest = AlphaTest::discardBelow(config.colorAlphaReference);
    return color;
}

// Composite (§3.5.4): out = (foliage, mask) blended SRC_ALPHA / INV_SRC_ALPHA onto the
// opaque colour = lerp(opaque, foliage, mask); the target's alpha is kept.
PipelineDesc compositePipelineDesc(ProgramHandle program) {
    PipelineDesc composite;
    composite.name = "ssam composite";
    composite.program = program;
    composite.blend[0] = BlendState::alphaOverKeepAlpha();
    return composite;
}

}  // namespace

ScreenSpaceAlphaMask::ScreenSpaceAlphaMask(Backend& backend, const Config& config) : backend_(backend) {
    config.validate();
    config_ = config;
    compositeProgram_ = backend_.createProgram(compositeProgram());
    try {
        pipelines_ = createPipelines(config_);
    } catch (...) {
        backend_.destroy(compositeProgram_);
        throw;
    }
}

ScreenSpaceAlphaMask::~ScreenSpaceAlphaMask() {
    destroy(pipelines_);
    destroyTargets();
    backend_.destroy(compositeProgram_);
}

void ScreenSpaceAlphaMask::setConfig(const Config& config) {
    config.validate();
    // The new pipelines first: if one cannot be made, the old configuration stays in force.
    const Pipelines next = createPipelines(config);
    destroy(pipelines_);
    pipelines_ = next;
    config_ = config;
}

ScreenSpaceAlphaMask::Pipelines ScreenSpaceAlphaMask::createPipelines(const Config& config) {
    Pipelines made;
    try {
        made.mask = backend_.createPipeline(maskPipelineDesc(config));
        made.color = backend_.createPipeline(colorPipelineDesc(config));
        made.composite = backend_.createPipeline(compositePipelineDesc(compositeProgram_));
    } catch (...) {
        destroy(made);
        throw;
    }
    return made;
}

void ScreenSpaceAlphaMask::destroy(const Pipelines& pipelines) {
    for (PipelineHandle p : {pipelines.mask, pipelines.color, pipelines.composite})
        if (p) backend_.destroy(p);
}

void ScreenSpaceAlphaMask::ensureTargets(int width, int height, Format foliageFormat) {
    if (width == width_ && height == height_ && foliageFormat_ == foliageFormat &&
        targetPrecision_ == config_.maskPrecision)
        return;
    destroyTargets();
    const IntermediateDescs descs = intermediateDescs(width, height, foliageFormat);
    mask_ = backend_.createTexture(descs.mask);
    if (descs.maskAdd) maskAdd_ = backend_.createTexture(*descs.maskAdd);
    foliage_ = backend_.createTexture(descs.foliage);
    width_ = width, height_ = height;
    foliageFormat_ = foliageFormat;
    targetPrecision_ = config_.maskPrecision;
}

IntermediateDescs ScreenSpaceAlphaMask::intermediateDescs(int width, int height, Format colorFormat) const {
    IntermediateDescs descs;
    switch (config_.maskPrecision) {
        case MaskPrecision::RGBA8: descs.mask = renderTargetDesc("rt_mask", width, height, Format::RGBA8_UNORM); break;
        case MaskPrecision::RGBA16F: descs.mask = renderTargetDesc("rt_mask", width, height, Format::RGBA16F); break;
        case MaskPrecision::RG16F:
            // Two R16F targets, one blend equation each (maskPipelineDesc).
            descs.mask = renderTargetDesc("rt_mask_max", width, height, Format::R16F);
            descs.maskAdd = renderTargetDesc("rt_mask_add", width, height, Format::R16F);
            break;
    }
    descs.foliage = renderTargetDesc("rt_foliage", width, height, colorFormat);
    return descs;
}

void ScreenSpaceAlphaMask::destroyTargets() {
    for (TextureHandle* t : {&mask_, &maskAdd_, &foliage_}) {
        if (*t) backend_.destroy(*t);
        *t = {};
    }
    width_ = height_ = 0;
    foliageFormat_.reset();
    targetPrecision_.reset();
}

FramePlan ScreenSpaceAlphaMask::plan(const FrameTargets& targets, const FoliageView& view) {
    const TextureDesc& color = backend_.describe(targets.color);
    return plan(color.width, color.height, color.format, view);
}

FramePlan ScreenSpaceAlphaMask::plan(int width, int height, Format colorFormat, const FoliageView& view) {
    FramePlan planned = cull(width, height, view);
    // Targets are only needed (and only created) once some foliage is in view.
    if (!planned.empty()) ensureTargets(planned.width, planned.height, colorFormat);
    return planned;
}

FramePlan ScreenSpaceAlphaMask::cull(int width, int height, const FoliageView& view) const {
    FramePlan plan;
    plan.width = width;
    plan.height = height;
    for (const MaskedBatch& batch : view.batches) {
        if (batch.count == 0 || batch.instanceCount == 0) continue;
        const std::optional<Rect> region = screenBounds(batch.worldBounds, view.viewProj, plan.width, plan.height);
        if (!region) continue;
        plan.visible.push_back(&batch);
        plan.compositeRegion = unite(plan.compositeRegion, *region);
    }
    return plan;
}

void ScreenSpaceAlphaMask::maskPass(const FramePlan& plan, const FoliageView& view, TextureHandle depth) {
    maskPass(plan, view, depth, intermediates());
}

void ScreenSpaceAlphaMask::colorPass(const FramePlan& plan, const FoliageView& view, TextureHandle depth) {
    colorPass(plan, view, depth, intermediates());
}

void ScreenSpaceAlphaMask::compositePass(const FramePlan& plan, TextureHandle color) {
    compositePass(plan, color, intermediates());
}

void ScreenSpaceAlphaMask::maskPass(const FramePlan& plan, const FoliageView& view, TextureHandle depth,
                                    const Intermediates& targets) {
    PassDesc pass;
    pass.name = "ssam mask";
    pass.color[0] = {targets.mask, LoadOp::Clear, glm::vec4(0.0f)};  // black background (§3.5.2)
    if (targets.maskAdd) pass.color[1] = {targets.maskAdd, LoadOp::Clear, glm::vec4(0.0f)};
    pass.depth = {depth, LoadOp::Load};
    PassScope passScope(backend_, pass);
    for (const MaskedBatch* batch : plan.visible) {
        AlphaOnlyParams params;
        params.viewProj = view.viewProj;
        params.alphaFactor = batch->baseColorFactor.a;
        params.baseColor = batch->baseColor;
        backend_.draw(maskedBatchDraw(*batch, pipelines_.mask, params));
    }
    passScope.end();
}

void ScreenSpaceAlphaMask::colorPass(const FramePlan& plan, const FoliageView& view, TextureHandle depth,
                                     const Intermediates& targets) {
    PassDesc pass;
    pass.name = "ssam colour";
    pass.color[0] = {targets.foliage, LoadOp::Clear, config_.foliageClearColor};  // the clear-colour fix (§3.6.1)
    pass.depth = {depth, LoadOp::Load};
    PassScope passScope(backend_, pass);
    for (const MaskedBatch* batch : plan.visible) {
        SurfaceParams params;
        params.viewProj = view.viewProj;
        params.baseColorFactor = batch->baseColorFactor;
        params.baseColor = batch->baseColor;
        params.light = batch->unlit ? engine::render::unlitLight() : view.light;
        backend_.draw(maskedBatchDraw(*batch, pipelines_.color, params));
    }
    passScope.end();
}

void ScreenSpaceAlphaMask::compositePass(const FramePlan& plan, TextureHandle color, const Intermediates& targets) {
    PassDesc pass;
    pass.name = "ssam composite";
    pass.color[0] = {color, LoadOp::Load};
    PassScope passScope(backend_, pass);
    CompositeParams params;
    params.foliage = targets.foliage;
    params.mask = targets.mask;
    params.maskAdd = targets.maskAdd;
    params.maskLerp = config_.maskLerp;
    params.squareMask = config_.squareMask;
    DrawDesc d;
    d.pipeline = pipelines_.composite;
    d.params = params;
    d.scissor = plan.compositeRegion;
    backend_.draw(d);
    passScope.end();
}

FrameReport ScreenSpaceAlphaMask::render(const FrameTargets& targets, const FoliageView& view) {
    const FramePlan p = plan(targets, view);
    FrameReport report;
    report.batchesVisible = static_cast<int>(p.visible.size());
    report.compositeRegion = p.compositeRegion;
    if (p.empty()) return report;  // no foliage in view: SSAM costs nothing
    maskPass(p, view, targets.depth);
    colorPass(p, view, targets.depth);
    compositePass(p, targets.color);
    report.passesRun = 3;
    return report;
}

}  // namespace ssam
