// SPDX-License-Identifier: MIT
#include "ssam/core/passes.hpp"

namespace ssam::core {

namespace {

constexpr TargetBlend oneOne(BlendOp color, BlendOp alpha) {
    return {true, BlendFactor::One, BlendFactor::One, color, BlendFactor::One, BlendFactor::One, alpha};
}

// 1. Mask pass (§3.5.2, Table 3.1): cleared to black; RGB = MAX, A = ADD, all ONE (Rg16f: MAX into
//    target 0, ADD into target 1, one blend equation each); depth test without write, both faces,
//    nothing rejected by alpha (the paper's reference of 0).
PassDescription maskPass(const Settings& s) {
    PassDescription p;
    p.kind = PassKind::Mask;
    p.name = "ssam mask";
    switch (s.maskPrecision) {
        case MaskPrecision::Rgba8:
        case MaskPrecision::Rgba16f:
            p.colorTargets[0].name = "rt_mask";
            p.colorTargets[0].format =
                s.maskPrecision == MaskPrecision::Rgba8 ? TargetFormat::Rgba8Unorm : TargetFormat::Rgba16f;
            p.colorTargets[0].blend = oneOne(BlendOp::Max, BlendOp::Add);
            break;
        case MaskPrecision::Rg16f:
            p.colorTargetCount = 2;
            p.colorTargets[0].name = "rt_mask_max";
            p.colorTargets[0].format = TargetFormat::R16f;
            p.colorTargets[0].blend = oneOne(BlendOp::Max, BlendOp::Max);
            p.colorTargets[1].name = "rt_mask_add";
            p.colorTargets[1].format = TargetFormat::R16f;
            p.colorTargets[1].blend = oneOne(BlendOp::Add, BlendOp::Add);
            break;
    }
    for (ColorTarget& t : p.colorTargets) t.clear = true;  // to black
    p.depthTest = true;
    p.depthCompare = s.depthTest;
    return p;
}

// 2. Colour pass (§3.5.3): cleared to the clear colour (§3.6.1); alpha test at the colour
//    reference; depth test and write into the host's depth (the foliage depth later passes use,
//    §3.7); both faces, no blending.
PassDescription colorPass(const Settings& s) {
    PassDescription p;
    p.kind = PassKind::Color;
    p.name = "ssam colour";
    p.colorTargets[0].name = "rt_foliage";
    p.colorTargets[0].format = TargetFormat::HostColor;
    p.colorTargets[0].clear = true;
    for (int c = 0; c < 4; ++c) p.colorTargets[0].clearColor[c] = s.foliageClearColor[c];
    p.depthTest = p.depthWrite = true;
    p.depthCompare = s.depthTest;
    p.alphaTest = true;
    p.alphaReference = s.colorAlphaReference;
    return p;
}

// 3. Composite (§3.5.4, Listing 3.2): (foliage, mask') blended SRC_ALPHA / ONE_MINUS_SRC_ALPHA onto
//    the host's colour = lerp(opaque, foliage, mask'), its alpha kept (ZERO / ONE); full screen,
//    scissored to the foliage's screen region, no depth.
PassDescription compositePass() {
    PassDescription p;
    p.kind = PassKind::Composite;
    p.name = "ssam composite";
    p.colorTargets[0].name = "host colour";
    p.colorTargets[0].blend = {true,         BlendFactor::SrcAlpha, BlendFactor::OneMinusSrcAlpha,
                               BlendOp::Add, BlendFactor::Zero,     BlendFactor::One,
                               BlendOp::Add};
    p.fullScreen = true;
    return p;
}

// 4. Depth restore (Settings::depthMaskThreshold > 0): where the composited mask is below the
//    threshold, the opaque depth saved before the colour pass is written back (depth written
//    unconditionally there, no colour); elsewhere the fragment is discarded.
PassDescription depthRestorePass() {
    PassDescription p;
    p.kind = PassKind::DepthRestore;
    p.name = "ssam depth restore";
    p.colorTargetCount = 0;
    p.depthWrite = true;
    p.fullScreen = true;
    return p;
}

}  // namespace

PassPlan describePasses(const Settings& settings) {
    PassPlan plan;
    plan.mask = maskPass(settings);
    plan.color = colorPass(settings);
    plan.composite = compositePass();
    plan.depthRestore = depthRestorePass();
    plan.restoresDepth = settings.depthMaskThreshold > 0.0f;
    return plan;
}

ColorFade colorFadeOf(const Settings& settings) {
    ColorFade fade;
    if (settings.colorFade > 0.0f) {
        fade.start = settings.colorAlphaReference;
        fade.end = settings.colorAlphaReference + settings.colorFade;
    }
    for (int c = 0; c < 3; ++c) fade.clearColor[c] = settings.foliageClearColor[c];
    return fade;
}

}  // namespace ssam::core
