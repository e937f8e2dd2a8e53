// SPDX-License-Identifier: MIT
#include "engine/render/resolved_draw_state.hpp"

#include <algorithm>

namespace engine::render {

namespace {

bool readsDstAlpha(BlendFactor factor) {
    return factor == BlendFactor::DstAlpha || factor == BlendFactor::InvDstAlpha || factor == BlendFactor::SrcAlphaSat;
}

FailModePlan planFor(const ResolvedDrawState& s, FailModeEmulation emulation) {
    if (emulation == FailModeEmulation::None) return {};
    return planFailMode({s.alphaTest, s.depthTest, s.depthWrite, s.depthFunc, s.anyRgbWrite, s.anyAlphaWrite,
                         s.rgbReadsDstAlpha, emulation == FailModeEmulation::PerTriangle});
}

}  // namespace

bool alphaTestCanMatter(const AlphaTest& test, bool depthWrite, bool anyRgbWrite, bool anyAlphaWrite) {
    if (!test.enabled || test.func == CompareFunc::Always) return false;
    switch (test.failMode) {
        case AlphaFailMode::Keep: return true;
        case AlphaFailMode::FbOnly: return depthWrite;
        case AlphaFailMode::ZbOnly: return anyRgbWrite || anyAlphaWrite;
        case AlphaFailMode::RgbOnly: return depthWrite || anyAlphaWrite;
    }
    return true;
}

bool rgbReadsDstAlpha(const BlendState& blend) {
    if (blend.isPlainWrite() || !(blend.writeMask & WriteRGB)) return false;
    if (blend.opRgb == BlendOp::Min || blend.opRgb == BlendOp::Max) return false;  // factors ignored
    return readsDstAlpha(blend.srcRgb) || readsDstAlpha(blend.dstRgb);
}

Rect clampScissor(const std::optional<Rect>& scissor, int width, int height) {
    if (!scissor) return {0, 0, width, height};
    const int x0 = std::max(0, scissor->x), y0 = std::max(0, scissor->y);
    const int x1 = std::min(width, scissor->x + scissor->width);
    const int y1 = std::min(height, scissor->y + scissor->height);
    return {x0, y0, std::max(0, x1 - x0), std::max(0, y1 - y0)};
}

ResolvedDrawState resolveDrawState(const PipelineDesc& pipeline, const DrawTargets& targets,
                                   const std::optional<Rect>& scissor, FailModeEmulation emulation) {
    ResolvedDrawState s;
    s.colorTargetCount = targets.colorTargetCount;
    s.blendConstant = pipeline.blendConstant;
    for (int i = 0; i < targets.colorTargetCount; ++i) {
        BlendState& b = s.blend[i] = pipeline.blend[i];
        const int channels = formatInfo(targets.colorFormats[i]).channels;
        b.writeMask &= std::uint8_t((1u << channels) - 1u);  // a fully masked target is not touched
        s.blendNeeded[i] = !b.isPlainWrite();
        s.anyRgbWrite = s.anyRgbWrite || (b.writeMask & WriteRGB);
        s.anyAlphaWrite = s.anyAlphaWrite || (b.writeMask & WriteA);
        s.rgbReadsDstAlpha = s.rgbReadsDstAlpha || rgbReadsDstAlpha(b);
    }
    s.depthTest = pipeline.depth.test && targets.hasDepth;
    s.depthWrite = s.depthTest && pipeline.depth.write;
    s.depthFunc = pipeline.depth.func;
    s.alphaTest = pipeline.alphaTest;
    s.alphaTest.enabled = alphaTestCanMatter(pipeline.alphaTest, s.depthWrite, s.anyRgbWrite, s.anyAlphaWrite);
    s.alphaTestDropped = pipeline.alphaTest.enabled && !s.alphaTest.enabled;
    // Alpha-to-coverage is ignored at one sample, as in GL.
    s.alphaToCoverage = pipeline.alphaTest.alphaToCoverage && targets.samples > 1;
    s.shade = s.anyRgbWrite || s.anyAlphaWrite || s.alphaTest.enabled || s.alphaToCoverage;
    s.scissor = clampScissor(scissor, targets.width, targets.height);
    s.failModes = planFor(s, emulation);
    return s;
}

ResolvedPipeline resolvePipeline(const PipelineDesc& pipeline, FailModeEmulation emulation) {
    // Before any pass: every blend state as given (all channels present), depth as asked.
    ResolvedDrawState s;
    bool plain = true;
    for (const BlendState& b : pipeline.blend) {
        s.anyRgbWrite = s.anyRgbWrite || (b.writeMask & WriteRGB);
        s.anyAlphaWrite = s.anyAlphaWrite || (b.writeMask & WriteA);
        s.rgbReadsDstAlpha = s.rgbReadsDstAlpha || rgbReadsDstAlpha(b);
        plain = plain && b.isPlainWrite();
    }
    s.depthTest = pipeline.depth.test;
    s.depthWrite = pipeline.depth.test && pipeline.depth.write;
    s.depthFunc = pipeline.depth.func;
    s.alphaTest = pipeline.alphaTest;
    s.alphaTest.enabled = alphaTestCanMatter(pipeline.alphaTest, s.depthWrite, s.anyRgbWrite, s.anyAlphaWrite);

    ResolvedPipeline r;
    r.info.alphaTestDropped = pipeline.alphaTest.enabled && !s.alphaTest.enabled;
    r.info.blendIsPlainWrite = plain;
    r.failModes = planFor(s, emulation);
    r.info.exact = r.failModes.exact;
    if (!r.failModes.exact) r.info.note = r.failModes.note;
    return r;
}

}  // namespace engine::render
