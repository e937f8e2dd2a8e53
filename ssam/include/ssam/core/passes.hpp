// SPDX-License-Identifier: MIT
#pragma once
// SSAM's passes as data ([Hathaway 2010] §3.5): for each pass its targets and their formats, how
// they start, the blend per target, the depth test and write, the alpha reference and culling.
// Every SSAM (the engine-hosted one, ssam::gl, ssam::vk) translates this description into its
// API and decides none of it itself: a change here reaches all three. A host that builds SSAM's
// state its own way may read it too. Each SSAM keeps the plan of its settings (describePasses()
// once per setSettings()), not one per pass.
#include "ssam/core/settings.hpp"

namespace ssam::core {

enum class BlendFactor : unsigned char { Zero, One, SrcAlpha, OneMinusSrcAlpha };
enum class BlendOp : unsigned char { Add, Max };

struct TargetBlend {
    bool enabled = false;
    BlendFactor srcColor = BlendFactor::One, dstColor = BlendFactor::Zero;
    BlendOp colorOp = BlendOp::Add;
    BlendFactor srcAlpha = BlendFactor::One, dstAlpha = BlendFactor::Zero;
    BlendOp alphaOp = BlendOp::Add;
};

// A pass's colour target. The host's colour is the composite's; rt_foliage takes its format.
enum class TargetFormat : unsigned char { Rgba8Unorm, Rgba16f, R16f, HostColor };

struct ColorTarget {
    const char* name = "";
    TargetFormat format = TargetFormat::HostColor;
    bool clear = false;  // cleared to clearColor when the pass begins, else loaded
    float clearColor[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    TargetBlend blend;
};

enum class PassKind : unsigned char { Mask, Color, Composite, DepthRestore };

struct PassDescription {
    PassKind kind = PassKind::Mask;
    const char* name = "";
    int colorTargetCount = 1;
    ColorTarget colorTargets[2];
    bool depthTest = false;  // against the host's depth, with `depthCompare`
    bool depthWrite = false;
    DepthTest depthCompare = DepthTest::Less;
    bool alphaTest = false;  // the colour pass: fragments with !(alpha >= alphaReference) are discarded
    float alphaReference = 0.0f;
    bool cullBackFaces = false;  // foliage cards are seen from both sides (§3.5.2-3)
    bool fullScreen = false;     // one triangle over the frame, scissored to the composite region
};

// The passes of a frame with foliage in view, in order. depthRestore runs only when
// Settings::depthMaskThreshold > 0 (after the composite; the opaque depth is copied before the
// colour pass). A host whose passes cannot write depth from a full-screen pass (the engine's
// backends) reaches the same depth another way: the colour pass into the copy, then the foliage
// again, depth only, where the mask reaches the threshold (ssam/src/foliage_depth_program.hpp).
struct PassPlan {
    PassDescription mask, color, composite, depthRestore;
    bool restoresDepth = false;
};

// The plan for `settings` (valid: settingsError() is empty).
PassPlan describePasses(const Settings& settings);

// Settings::colorFade as every composite reads it: the MAX-mask values the fade runs between
// (end > start) and the colour it fades from; end == start == 0 when the knob is off.
struct ColorFade {
    float start = 0.0f, end = 0.0f;
    float clearColor[3] = {0.0f, 0.0f, 0.0f};
};
ColorFade colorFadeOf(const Settings& settings);

}  // namespace ssam::core
