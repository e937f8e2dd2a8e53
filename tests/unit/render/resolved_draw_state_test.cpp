// SPDX-License-Identifier: MIT
// The draw-state resolver against its rules: random pipeline + pass pairs, each field of the
// result checked against the rule written out here a second way (what a failing fragment
// writes against what a passing one writes; the scissor pixel by pixel), so a rule changed in
// the resolver alone fails here.
#include <gtest/gtest.h>

#include <optional>
#include <random>

#include "engine/render/resolved_draw_state.hpp"

namespace engine::render {
namespace {

constexpr Format kColorFormats[] = {Format::RGBA8_UNORM, Format::RGBA8_SRGB, Format::R8_UNORM,
                                    Format::RG8_UNORM,   Format::RGBA16F,    Format::RG16F,
                                    Format::R16F,        Format::RGBA32F,    Format::R32F};

struct RandomState {
    std::mt19937 rng{20101005u};

    int below(int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng); }
    bool coin() { return below(2) == 1; }
    template <typename T, std::size_t N>
    T pick(const T (&values)[N]) {
        return values[below(int(N))];
    }

    BlendState blend() {
        BlendState b;
        b.enabled = coin();
        // Plain halves often, so that blendNeeded is false as often as true.
        const bool plainRgb = coin(), plainAlpha = coin();
        b.srcRgb = plainRgb ? BlendFactor::One : pick(kAllBlendFactors);
        b.dstRgb = plainRgb ? BlendFactor::Zero : pick(kAllBlendFactors);
        b.opRgb = plainRgb ? BlendOp::Add : pick(kAllBlendOps);
        b.srcAlpha = plainAlpha ? BlendFactor::One : pick(kAllBlendFactors);
        b.dstAlpha = plainAlpha ? BlendFactor::Zero : pick(kAllBlendFactors);
        b.opAlpha = plainAlpha ? BlendOp::Add : pick(kAllBlendOps);
        b.writeMask = std::uint8_t(below(16));
        return b;
    }

    PipelineDesc pipeline() {
        PipelineDesc p;
        for (BlendState& b : p.blend) b = blend();
        p.blendConstant = glm::vec4(float(below(5)) / 4.0f);
        p.depth = {coin(), coin(), pick(kAllCompareFuncs)};
        p.alphaTest = {coin(), pick(kAllCompareFuncs), float(below(5)) / 4.0f, pick(kAllAlphaFailModes), coin()};
        return p;
    }

    DrawTargets targets() {
        DrawTargets t;
        t.colorTargetCount = below(kMaxColorTargets + 1);
        for (int i = 0; i < t.colorTargetCount; ++i) t.colorFormats[i] = pick(kColorFormats);
        t.hasDepth = coin();
        t.samples = 1 << below(3);
        t.width = 1 + below(16);
        t.height = 1 + below(16);
        return t;
    }

    std::optional<Rect> scissor() {
        if (below(4) == 0) return std::nullopt;
        return Rect{below(40) - 20, below(40) - 20, below(40) - 10, below(40) - 10};
    }
};

bool plainHalf(BlendFactor src, BlendFactor dst, BlendOp op) {
    return src == BlendFactor::One && dst == BlendFactor::Zero && op == BlendOp::Add;
}

// What a fragment writes, as bits: R G B A, then depth.
constexpr unsigned kRgb = 7, kAlpha = 8, kDepth = 16;

// The rule for an alpha test that cannot change the result, from what each fragment class
// writes ([PCSX2] "Looking further"): it matters when a failing fragment writes something
// else than a passing one, and always for KEEP (a discarded fragment is not even counted).
bool testMatters(const AlphaTest& test, bool anyRgb, bool anyAlpha, bool depthWrite) {
    if (!test.enabled || test.func == CompareFunc::Always) return false;
    const unsigned written = (anyRgb ? kRgb : 0u) | (anyAlpha ? kAlpha : 0u) | (depthWrite ? kDepth : 0u);
    unsigned failing = 0;
    switch (test.failMode) {
        case AlphaFailMode::Keep: return true;
        case AlphaFailMode::FbOnly: failing = kRgb | kAlpha; break;
        case AlphaFailMode::ZbOnly: failing = kDepth; break;
        case AlphaFailMode::RgbOnly: failing = kRgb; break;
    }
    return (failing & written) != written;
}

bool insideRect(const Rect& r, int x, int y) { return x >= r.x && y >= r.y && x < r.x + r.width && y < r.y + r.height; }

void expectResolvedByTheRules(const PipelineDesc& p, const DrawTargets& t, const std::optional<Rect>& scissor,
                              const ResolvedDrawState& s) {
    ASSERT_EQ(s.colorTargetCount, t.colorTargetCount);
    bool anyRgb = false, anyAlpha = false;
    for (int i = 0; i < kMaxColorTargets; ++i) {
        SCOPED_TRACE(testing::Message() << "target " << i);
        if (i >= t.colorTargetCount) {  // nothing bound: nothing written, nothing blended
            EXPECT_FALSE(s.blendNeeded[i]);
            continue;
        }
        const int channels = formatInfo(t.colorFormats[i]).channels;
        const unsigned present = channels == 1 ? 0x1u : channels == 2 ? 0x3u : 0xFu;
        EXPECT_EQ(s.blend[i].writeMask, p.blend[i].writeMask & present);
        const BlendState& b = p.blend[i];
        const bool plain =
            !b.enabled || (plainHalf(b.srcRgb, b.dstRgb, b.opRgb) && plainHalf(b.srcAlpha, b.dstAlpha, b.opAlpha));
        EXPECT_EQ(s.blendNeeded[i], !plain);
        EXPECT_EQ(s.blend[i].srcRgb, b.srcRgb);
        EXPECT_EQ(s.blend[i].opAlpha, b.opAlpha);
        anyRgb = anyRgb || (s.blend[i].writeMask & kRgb);
        anyAlpha = anyAlpha || (s.blend[i].writeMask & kAlpha);
    }
    EXPECT_EQ(s.anyRgbWrite, anyRgb);
    EXPECT_EQ(s.anyAlphaWrite, anyAlpha);
    EXPECT_EQ(s.blendConstant, p.blendConstant);

    EXPECT_EQ(s.depthTest, p.depth.test && t.hasDepth);
    EXPECT_EQ(s.depthWrite, p.depth.test && t.hasDepth && p.depth.write);
    EXPECT_EQ(s.depthFunc, p.depth.func);

    const bool matters = testMatters(p.alphaTest, anyRgb, anyAlpha, s.depthWrite);
    EXPECT_EQ(s.alphaTest.enabled, matters);
    EXPECT_EQ(s.alphaTestDropped, p.alphaTest.enabled && !matters);
    EXPECT_EQ(s.alphaTest.func, p.alphaTest.func);
    EXPECT_EQ(s.alphaTest.reference, p.alphaTest.reference);
    EXPECT_EQ(s.alphaTest.failMode, p.alphaTest.failMode);
    const bool coverage = p.alphaTest.alphaToCoverage && t.samples > 1;  // ignored at 1 sample, as in GL
    EXPECT_EQ(s.alphaToCoverage, coverage);
    EXPECT_EQ(s.shade, anyRgb || anyAlpha || matters || coverage);

    // The scissor, pixel by pixel: a pixel is in it when it is in the draw's scissor (all of
    // the target without one) and in the target.
    bool anyInside = false;
    for (int y = -24; y < 40; ++y) {
        for (int x = -24; x < 40; ++x) {
            const bool inTarget = x >= 0 && y >= 0 && x < t.width && y < t.height;
            const bool expected = inTarget && (!scissor || insideRect(*scissor, x, y));
            anyInside = anyInside || expected;
            ASSERT_EQ(insideRect(s.scissor, x, y), expected) << "pixel " << x << "," << y;
        }
    }
    EXPECT_EQ(s.scissor.empty(), !anyInside);
    EXPECT_GE(s.scissor.width, 0);
    EXPECT_GE(s.scissor.height, 0);
}

TEST(ResolvedDrawState, RandomPipelinesAndPassesFollowEveryRule) {
    RandomState random;
    int dropped = 0, kept = 0, blended = 0, emptyScissors = 0;
    for (int n = 0; n < 4000; ++n) {
        const PipelineDesc p = random.pipeline();
        const DrawTargets t = random.targets();
        const std::optional<Rect> scissor = random.scissor();
        SCOPED_TRACE(testing::Message() << "case " << n);
        const ResolvedDrawState s = resolveDrawState(p, t, scissor, FailModeEmulation::None);
        expectResolvedByTheRules(p, t, scissor, s);
        if (HasFatalFailure()) return;
        EXPECT_TRUE(s.failModes.steps.empty()) << "no plan without emulation";
        dropped += s.alphaTestDropped;
        kept += s.alphaTest.enabled;
        blended += s.blendNeeded[0];
        emptyScissors += s.scissor.empty();
    }
    // The random cases reach both sides of each rule.
    EXPECT_GT(dropped, 100);
    EXPECT_GT(kept, 100);
    EXPECT_GT(blended, 100);
    EXPECT_GT(emptyScissors, 100);
}

TEST(ResolvedDrawState, EmulatedFailModesArePlannedFromTheResolvedState) {
    RandomState random;
    for (int n = 0; n < 2000; ++n) {
        const PipelineDesc p = random.pipeline();
        const DrawTargets t = random.targets();
        const ResolvedDrawState s = resolveDrawState(p, t, std::nullopt, FailModeEmulation::TwoPass);
        SCOPED_TRACE(testing::Message() << "case " << n);
        ASSERT_FALSE(s.failModes.steps.empty());
        // A test that cannot matter is one step over all fragments with the draw's own depth write.
        if (!s.alphaTest.enabled) {
            ASSERT_EQ(s.failModes.steps.size(), 1u);
            EXPECT_EQ(s.failModes.steps[0].select, FragmentSelect::All);
            EXPECT_EQ(s.failModes.steps[0].depthWrite, s.depthWrite);
        }
        // No step writes depth the draw does not write.
        for (const PlanStep& step : s.failModes.steps) EXPECT_TRUE(!step.depthWrite || s.depthWrite);
        EXPECT_FALSE(s.failModes.perTriangle) << "per-triangle steps only when the driver allows them";
    }
}

TEST(ResolvedDrawState, APipelineAloneIsResolvedAsForFullTargets) {
    RandomState random;
    DrawTargets full;
    full.colorTargetCount = kMaxColorTargets;
    full.colorFormats.fill(Format::RGBA8_UNORM);
    full.hasDepth = true;
    full.width = full.height = 8;
    for (int n = 0; n < 2000; ++n) {
        const PipelineDesc p = random.pipeline();
        const ResolvedPipeline r = resolvePipeline(p, FailModeEmulation::TwoPass);
        const ResolvedDrawState s = resolveDrawState(p, full, std::nullopt, FailModeEmulation::TwoPass);
        SCOPED_TRACE(testing::Message() << "case " << n);
        EXPECT_EQ(r.info.alphaTestDropped, s.alphaTestDropped);
        bool plain = true;
        for (const BlendState& b : p.blend) plain = plain && b.isPlainWrite();
        EXPECT_EQ(r.info.blendIsPlainWrite, plain);
        EXPECT_EQ(r.info.exact, s.failModes.exact);
        EXPECT_EQ(r.info.note.empty(), r.info.exact) << "a note says why, exactly when inexact";
        EXPECT_TRUE(resolvePipeline(p, FailModeEmulation::None).info.exact) << "native fail modes are exact";
    }
}

TEST(ResolvedDrawState, NamedCases) {
    PipelineDesc p;
    p.alphaTest = AlphaTest::discardBelow(0.5f);
    DrawTargets t;
    t.colorTargetCount = 1;
    t.colorFormats[0] = Format::RG16F;
    t.width = t.height = 4;
    ResolvedDrawState s = resolveDrawState(p, t, std::nullopt, FailModeEmulation::None);
    EXPECT_EQ(s.blend[0].writeMask, WriteR | WriteG) << "an RG target has no blue or alpha to write";
    EXPECT_TRUE(s.alphaTest.enabled) << "a discard always matters";
    // FB_ONLY without depth writes writes what a passing fragment writes ([PCSX2]).
    p.alphaTest.failMode = AlphaFailMode::FbOnly;
    p.depth = DepthState::testAndWrite();
    s = resolveDrawState(p, t, std::nullopt, FailModeEmulation::None);
    EXPECT_TRUE(s.alphaTestDropped) << "no depth target bound: no depth write";
    t.hasDepth = true;
    s = resolveDrawState(p, t, std::nullopt, FailModeEmulation::None);
    EXPECT_FALSE(s.alphaTestDropped);
    // Fully masked: depth only, nothing to shade.
    p.blend[0].writeMask = 0;
    p.alphaTest = AlphaTest::off();
    s = resolveDrawState(p, t, std::nullopt, FailModeEmulation::None);
    EXPECT_FALSE(s.shade);
    // Alpha-to-coverage shades even then, but only with samples to cover.
    p.alphaTest.alphaToCoverage = true;
    EXPECT_FALSE(resolveDrawState(p, t, std::nullopt, FailModeEmulation::None).shade);
    t.samples = 4;
    EXPECT_TRUE(resolveDrawState(p, t, std::nullopt, FailModeEmulation::None).shade);
    // The scissor is cut to the target.
    const Rect clamped = clampScissor(Rect{-3, 2, 5, 10}, 4, 4);
    EXPECT_EQ(clamped.x, 0);
    EXPECT_EQ(clamped.y, 2);
    EXPECT_EQ(clamped.width, 2);
    EXPECT_EQ(clamped.height, 2);
}

TEST(ResolvedDrawState, RgbReadsDestinationAlphaOnlyThroughItsFactors) {
    BlendState b = BlendState::alphaOver();
    EXPECT_FALSE(rgbReadsDstAlpha(b));
    b.dstRgb = BlendFactor::InvDstAlpha;
    EXPECT_TRUE(rgbReadsDstAlpha(b));
    b.opRgb = BlendOp::Max;  // MIN and MAX ignore the factors
    EXPECT_FALSE(rgbReadsDstAlpha(b));
    b.opRgb = BlendOp::Add;
    b.writeMask = WriteA;  // no RGB written
    EXPECT_FALSE(rgbReadsDstAlpha(b));
    b = BlendState::opaque();
    b.srcRgb = BlendFactor::SrcAlphaSat;  // min(src.a, 1 - dst.a), but blending is off
    EXPECT_FALSE(rgbReadsDstAlpha(b));
    b.enabled = true;
    EXPECT_TRUE(rgbReadsDstAlpha(b));
}

}  // namespace
}  // namespace engine::render
