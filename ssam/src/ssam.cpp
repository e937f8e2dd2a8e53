// SPDX-License-Identifier: MIT
#include "ssam/ssam.hpp"

#include "ssam/core/passes.hpp"
#include "foliage_depth_program.hpp"
#include "engine/core/error.hpp"
#include "engine/render/pass_scope.hpp"
#include "engine/render/screen_bounds.hpp"
#include "ssam/composite_program.hpp"

namespace ssam {

using namespace engine::render;

namespace {

// The engine's spelling of the core's plan (core/passes.hpp): no SSAM decision is made here.
BlendFactor toBlendFactor(core::BlendFactor f) {
    switch (f) {
        case core::BlendFactor::Zero: return BlendFactor::Zero;
        case core::BlendFactor::One: return BlendFactor::One;
        case core::BlendFactor::SrcAlpha: return BlendFactor::SrcAlpha;
        case core::BlendFactor::OneMinusSrcAlpha: return BlendFactor::InvSrcAlpha;
    }
    return BlendFactor::One;
}

BlendOp toBlendOp(core::BlendOp op) { return op == core::BlendOp::Max ? BlendOp::Max : BlendOp::Add; }

BlendState toBlendState(const core::TargetBlend& b) {
    if (!b.enabled) return BlendState::opaque();
    return {true,
            toBlendFactor(b.srcColor),
            toBlendFactor(b.dstColor),
            toBlendOp(b.colorOp),
            toBlendFactor(b.srcAlpha),
            toBlendFactor(b.dstAlpha),
            toBlendOp(b.alphaOp),
            WriteAll};
}

Format toFormat(core::TargetFormat format, Format hostColor) {
    switch (format) {
        case core::TargetFormat::Rgba8Unorm: return Format::RGBA8_UNORM;
        case core::TargetFormat::Rgba16f: return Format::RGBA16F;
        case core::TargetFormat::R16f: return Format::R16F;
        case core::TargetFormat::HostColor: return hostColor;
    }
    return hostColor;
}

// A foliage pass's pipeline (the mask and colour passes draw the host's batches with the engine's
// standard programs) or the composite's (SSAM's full-screen program).
PipelineDesc pipelineDesc(const core::PassDescription& pass, ProgramHandle fullScreenProgram) {
    PipelineDesc d;
    d.name = pass.name;
    if (pass.fullScreen) d.program = fullScreenProgram;
    else d.program = pass.kind == core::PassKind::Mask ? ProgramKind::AlphaOnly : ProgramKind::MaskedLit;
    if (pass.depthTest)
        d.depth = pass.depthWrite ? DepthState::testAndWrite(compareFuncOf(pass.depthCompare))
                                  : DepthState::testOnly(compareFuncOf(pass.depthCompare));
    d.raster.cull = pass.cullBackFaces ? CullMode::Back : CullMode::None;
    if (pass.alphaTest) d.alphaTest = AlphaTest::discardBelow(pass.alphaReference);
    for (int t = 0; t < pass.colorTargetCount; ++t) d.blend[t] = toBlendState(pass.colorTargets[t].blend);
    return d;
}

// The colour pass's surface for `batch`: the view's sun unless the batch is unlit.
SurfaceParams surfaceOf(const MaskedBatch& batch, const FoliageView& view) {
    SurfaceParams params;
    params.viewProj = view.viewProj;
    params.baseColorFactor = batch.baseColorFactor;
    params.baseColor = batch.baseColor;
    params.light = batch.unlit ? engine::render::unlitLight() : view.light;
    return params;
}

glm::vec4 clearColorOf(const core::ColorTarget& target) {
    return {target.clearColor[0], target.clearColor[1], target.clearColor[2], target.clearColor[3]};
}

// One of the core's foliage passes (its name, its first target cleared as it says) into `color`,
// on `depth` as it is.
PassDesc foliagePassOf(const core::PassDescription& description, TextureHandle color, TextureHandle depth) {
    PassDesc pass;
    pass.name = description.name;
    pass.color[0] = {color, LoadOp::Clear, clearColorOf(description.colorTargets[0])};
    pass.depth = {depth, LoadOp::Load};
    return pass;
}

}  // namespace

CompareFunc compareFuncOf(DepthTest test) {
    switch (test) {
        case DepthTest::Less: return CompareFunc::Less;
        case DepthTest::LessEqual: return CompareFunc::LessEqual;
        case DepthTest::Greater: return CompareFunc::Greater;
        case DepthTest::GreaterEqual: return CompareFunc::GreaterEqual;
    }
    return CompareFunc::Less;
}

std::optional<DepthTest> depthTestOf(CompareFunc func) {
    for (DepthTest test : {DepthTest::Less, DepthTest::LessEqual, DepthTest::Greater, DepthTest::GreaterEqual})
        if (compareFuncOf(test) == func) return test;
    return std::nullopt;
}

namespace {

void throwIfInvalid(const Settings& settings) {
    if (const std::string error = settingsError(settings); !error.empty()) throw engine::Error(error);
}

}  // namespace

ScreenSpaceAlphaMask::ScreenSpaceAlphaMask(Backend& backend, const Settings& settings) : backend_(backend) {
    throwIfInvalid(settings);
    settings_ = settings;
    passes_ = core::describePasses(settings_);
    compositeProgram_ = backend_.createProgram(compositeProgram());
    try {
        pipelines_ = createPipelines(settings_);
    } catch (...) {
        backend_.destroy(compositeProgram_);
        throw;
    }
}

ScreenSpaceAlphaMask::~ScreenSpaceAlphaMask() {
    destroy(pipelines_);
    backend_.destroy(compositeProgram_);
}

void ScreenSpaceAlphaMask::setSettings(const Settings& settings) {
    throwIfInvalid(settings);
    // The new pipelines first: if one cannot be made, the old settings stay in force.
    const Pipelines next = createPipelines(settings);
    destroy(pipelines_);
    pipelines_ = next;
    settings_ = settings;
    passes_ = core::describePasses(settings_);
}

ScreenSpaceAlphaMask::Pipelines ScreenSpaceAlphaMask::createPipelines(const Settings& settings) {
    const core::PassPlan passes = core::describePasses(settings);
    Pipelines made;
    try {
        made.mask = backend_.createPipeline(pipelineDesc(passes.mask, {}));
        made.color = backend_.createPipeline(pipelineDesc(passes.color, {}));
        made.composite = backend_.createPipeline(pipelineDesc(passes.composite, compositeProgram_));
        if (passes.restoresDepth) {
            // The depth restore's result, drawn as the engine can (foliage_depth_program.hpp): the
            // colour pass's depth state and alpha test, no colour target.
            made.foliageDepthProgram = backend_.createProgram(foliageDepthProgram());
            PipelineDesc d = pipelineDesc(passes.color, {});
            d.name = passes.depthRestore.name;
            d.program = made.foliageDepthProgram;
            d.blend[0] = BlendState::opaque();
            made.foliageDepth = backend_.createPipeline(d);
        }
    } catch (...) {
        destroy(made);
        throw;
    }
    return made;
}

void ScreenSpaceAlphaMask::destroy(const Pipelines& pipelines) {
    for (PipelineHandle p : {pipelines.mask, pipelines.color, pipelines.composite, pipelines.foliageDepth})
        if (p) backend_.destroy(p);
    if (pipelines.foliageDepthProgram) backend_.destroy(pipelines.foliageDepthProgram);
}

IntermediateDescs ScreenSpaceAlphaMask::intermediateDescs(int width, int height, Format colorFormat) const {
    const core::PassPlan& passes = passes_;
    const auto desc = [&](const core::ColorTarget& target) {
        return renderTargetDesc(target.name, width, height, toFormat(target.format, colorFormat));
    };
    IntermediateDescs descs;
    descs.mask = desc(passes.mask.colorTargets[0]);
    if (passes.mask.colorTargetCount == 2) descs.maskAdd = desc(passes.mask.colorTargets[1]);
    descs.foliage = desc(passes.color.colorTargets[0]);
    if (passes.restoresDepth) descs.depthCopy = renderTargetDesc("rt_depth_copy", width, height, Format::D32F);
    return descs;
}

FramePlan ScreenSpaceAlphaMask::cull(int width, int height, const FoliageView& view) const {
    FramePlan plan;
    plan.width = width;
    plan.height = height;
    for (const MaskedBatch& batch : view.batches) {
        if (batch.count == 0 || batch.instanceCount == 0) continue;
        const std::optional<engine::render::Rect> region =
            screenBounds(batch.worldBounds, view.viewProj, plan.width, plan.height);
        if (!region) continue;
        plan.visible.push_back(&batch);
        plan.compositeRegion = unite(plan.compositeRegion, *region);
    }
    return plan;
}

void ScreenSpaceAlphaMask::maskPass(const FramePlan& plan, const FoliageView& view, TextureHandle depth,
                                    const Intermediates& targets) {
    PassDesc pass = foliagePassOf(passes_.mask, targets.mask, depth);
    if (targets.maskAdd) pass.color[1] = {targets.maskAdd, LoadOp::Clear, clearColorOf(passes_.mask.colorTargets[1])};
    PassScope passScope(backend_, pass);
    for (const MaskedBatch* batch : plan.visible) {
        const AlphaOnlyParams params{view.viewProj, batch->baseColorFactor.a, batch->baseColor};
        backend_.draw(maskedBatchDraw(*batch, pipelines_.mask, params));
    }
    passScope.end();
}

void ScreenSpaceAlphaMask::colorPass(const FramePlan& plan, const FoliageView& view, TextureHandle depth,
                                     const Intermediates& targets) {
    PassDesc pass = foliagePassOf(passes_.color, targets.foliage, depth);
    if (targets.depthCopy) {
        // depthMaskThreshold > 0: the colour pass picks the nearest leaf in a copy of the opaque
        // depth; the host's depth gets the foliage later (foliageDepthPass), where the mask allows.
        backend_.resolve({depth, targets.depthCopy, compareFuncOf(settings_.depthTest)});
        pass.depth.texture = targets.depthCopy;
    }
    PassScope passScope(backend_, pass);
    for (const MaskedBatch* batch : plan.visible)
        backend_.draw(maskedBatchDraw(*batch, pipelines_.color, surfaceOf(*batch, view)));
    passScope.end();
}

CompositeParams ScreenSpaceAlphaMask::compositeParams(const Intermediates& targets) const {
    const core::ColorFade fade = core::colorFadeOf(settings_);
    return {targets.foliage,
            targets.mask,
            targets.maskAdd,
            settings_.maskLerp,
            settings_.squareMask,
            {fade.start, fade.end},
            {fade.clearColor[0], fade.clearColor[1], fade.clearColor[2]},
            settings_.colorBlur};
}

void ScreenSpaceAlphaMask::compositePass(const FramePlan& plan, TextureHandle color, const Intermediates& targets) {
    PassDesc pass;
    pass.name = passes_.composite.name;
    pass.color[0] = {color, LoadOp::Load};
    PassScope passScope(backend_, pass);
    DrawDesc d;
    d.pipeline = pipelines_.composite;
    d.params = compositeParams(targets);
    d.scissor = plan.compositeRegion;
    backend_.draw(d);
    passScope.end();
}

void ScreenSpaceAlphaMask::foliageDepthPass(const FramePlan& plan, const FoliageView& view, TextureHandle depth,
                                            const Intermediates& targets) {
    if (!pipelines_.foliageDepth) return;  // depthMaskThreshold 0: the colour pass wrote the host's depth
    PassDesc pass;
    pass.name = passes_.depthRestore.name;
    pass.depth = {depth, LoadOp::Load};
    PassScope passScope(backend_, pass);
    const CompositeParams mask = compositeParams(targets);
    for (const MaskedBatch* batch : plan.visible)
        backend_.draw(maskedBatchDraw(*batch, pipelines_.foliageDepth,
                                      foliageDepthParams(surfaceOf(*batch, view), mask, settings_.depthMaskThreshold)));
    passScope.end();
}

}  // namespace ssam
