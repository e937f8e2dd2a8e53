// SPDX-License-Identifier: MIT
// SSAM's host-neutral core (ssam/core/): the settings' rules and messages, the presets, the status
// names, and the passes as data that every SSAM translates ([Hathaway 2010] §3.5).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <string>

#include "ssam/core/passes.hpp"
#include "ssam/core/frame.hpp"
#include "ssam/core/settings.hpp"
#include "ssam/core/status.hpp"

namespace {

void expectSameKnobs(const ssam::Settings& a, const ssam::Settings& b) {
    EXPECT_EQ(a.maskLerp, b.maskLerp);
    EXPECT_EQ(a.colorAlphaReference, b.colorAlphaReference);
    EXPECT_TRUE(std::equal(std::begin(a.foliageClearColor), std::end(a.foliageClearColor), b.foliageClearColor));
    EXPECT_EQ(a.squareMask, b.squareMask);
    EXPECT_EQ(a.maskPrecision, b.maskPrecision);
    EXPECT_EQ(a.depthTest, b.depthTest);
    EXPECT_EQ(a.depthMaskThreshold, b.depthMaskThreshold);
    EXPECT_EQ(a.colorFade, b.colorFade);
    EXPECT_EQ(a.colorBlur, b.colorBlur);
}

TEST(SsamCore, SettingsHoldEveryKnobOnce) {
    // A knob added to Settings must reach the engine-hosted SSAM, ssam::gl and ssam::vk (each
    // translates describePasses() or reads the knob) and expectSameKnobs above: this size is the
    // reminder, changed together with them.
    EXPECT_EQ(sizeof(ssam::Settings), 40u);
}

TEST(SsamCore, PaperIsTheDefaultSettings) {
    expectSameKnobs(ssam::presetSettings(ssam::Preset::Paper), ssam::Settings{});
}

TEST(SsamCore, MeasuredChangesOnlyTheMaskKnobsAndIsValid) {
    const ssam::Settings paper;
    const ssam::Settings measured = ssam::presetSettings(ssam::Preset::Measured);
    EXPECT_EQ(ssam::settingsError(measured), "");
    EXPECT_FALSE(measured.squareMask);  // §3.6.2's trick off: the bias knobs.md measured
    EXPECT_EQ(measured.maskLerp, 0.9f);
    EXPECT_EQ(measured.colorAlphaReference, 96.0f / 255.0f);
    // The cost knob stays the paper's: a float mask costs +46% on soft (knobs.md), over the 1.25x budget.
    EXPECT_EQ(measured.maskPrecision, paper.maskPrecision);
    EXPECT_TRUE(std::equal(std::begin(measured.foliageClearColor), std::end(measured.foliageClearColor),
                           paper.foliageClearColor));
    EXPECT_EQ(measured.depthTest, paper.depthTest);
    EXPECT_EQ(measured.depthMaskThreshold, paper.depthMaskThreshold);
    EXPECT_EQ(measured.colorFade, paper.colorFade);  // off: ssam/docs/steady_in_motion.md
    EXPECT_TRUE(measured.colorBlur);                 // on: the same page, idea 4
    EXPECT_FALSE(paper.colorBlur);
}

TEST(SsamCore, PresetNamesRoundTripAndUnknownNamesAreRefused) {
    for (ssam::Preset p : {ssam::Preset::Paper, ssam::Preset::Measured})
        EXPECT_EQ(ssam::parsePreset(ssam::presetName(p)), p);
    EXPECT_EQ(std::string(ssam::presetName(ssam::Preset::Paper)), "paper");
    EXPECT_EQ(std::string(ssam::presetName(ssam::Preset::Measured)), "measured");
    EXPECT_FALSE(ssam::parsePreset("Paper").has_value());
    EXPECT_FALSE(ssam::parsePreset("").has_value());
    EXPECT_EQ(ssam::kRecommendedPreset, ssam::Preset::Measured);
}

// Each refusal names the knob and the value it was given.
TEST(SsamCore, SettingsErrorsNameTheKnobAndTheValue) {
    struct Case {
        const char* knob;
        void (*spoil)(ssam::Settings&);
        const char* value;
    };
    const Case cases[] = {
        {"maskLerp", [](ssam::Settings& s) { s.maskLerp = 1.5f; }, "1.5"},
        {"maskLerp", [](ssam::Settings& s) { s.maskLerp = NAN; }, "nan"},
        {"colorAlphaReference", [](ssam::Settings& s) { s.colorAlphaReference = -0.25f; }, "-0.25"},
        {"depthMaskThreshold", [](ssam::Settings& s) { s.depthMaskThreshold = INFINITY; }, "inf"},
        {"colorFade", [](ssam::Settings& s) { s.colorFade = 1.5f; }, "1.5"},
        {"foliageClearColor[2]", [](ssam::Settings& s) { s.foliageClearColor[2] = NAN; }, "nan"},
        {"maskPrecision", [](ssam::Settings& s) { s.maskPrecision = static_cast<ssam::MaskPrecision>(7); }, "7"},
        {"depthTest", [](ssam::Settings& s) { s.depthTest = static_cast<ssam::DepthTest>(4); }, "4"},
    };
    for (const Case& c : cases) {
        ssam::Settings s;
        c.spoil(s);
        const std::string error = ssam::settingsError(s);
        EXPECT_NE(error.find(c.knob), std::string::npos) << error;
        EXPECT_NE(error.find(c.value), std::string::npos) << error;
    }
    EXPECT_EQ(ssam::settingsError({}), "");
}

TEST(SsamCore, EveryStatusAndEnumHasAName) {
    for (int s = 0; s <= static_cast<int>(ssam::Status::DeviceError); ++s)
        EXPECT_STRNE(ssam::statusName(static_cast<ssam::Status>(s)), "unknown status") << s;
    EXPECT_STREQ(ssam::statusName(ssam::Status::Ok), "ok");
    EXPECT_STREQ(ssam::maskPrecisionName(ssam::MaskPrecision::Rg16f), "rg16f");
    EXPECT_STREQ(ssam::depthTestName(ssam::DepthTest::GreaterEqual), "greater-equal");
    EXPECT_STREQ(ssam::foliagePassName(ssam::FoliagePass::Color), "colour");
    EXPECT_STREQ(ssam::severityName(ssam::Severity::Warning), "warning");
}

// The plan is the paper's: Table 3.1's mask blend, §3.5.3's colour pass, Listing 3.2's composite.
TEST(SsamCore, PassesAreThePapers) {
    using namespace ssam::core;
    ssam::Settings s;
    s.depthTest = ssam::DepthTest::GreaterEqual;
    s.colorAlphaReference = 0.25f;
    const PassPlan rgba8 = describePasses(s);
    EXPECT_EQ(rgba8.mask.colorTargetCount, 1);
    EXPECT_EQ(rgba8.mask.colorTargets[0].format, TargetFormat::Rgba8Unorm);
    EXPECT_EQ(rgba8.mask.colorTargets[0].blend.colorOp, BlendOp::Max);
    EXPECT_EQ(rgba8.mask.colorTargets[0].blend.alphaOp, BlendOp::Add);
    EXPECT_TRUE(rgba8.mask.depthTest);
    EXPECT_FALSE(rgba8.mask.depthWrite);
    EXPECT_FALSE(rgba8.mask.alphaTest);
    EXPECT_EQ(rgba8.mask.depthCompare, ssam::DepthTest::GreaterEqual);
    EXPECT_TRUE(rgba8.color.depthTest && rgba8.color.depthWrite && rgba8.color.alphaTest);
    EXPECT_EQ(rgba8.color.alphaReference, 0.25f);
    EXPECT_EQ(rgba8.color.colorTargets[0].clearColor[1], s.foliageClearColor[1]);
    EXPECT_FALSE(rgba8.color.colorTargets[0].blend.enabled);
    EXPECT_TRUE(rgba8.composite.fullScreen);
    EXPECT_EQ(rgba8.composite.colorTargets[0].blend.dstColor, BlendFactor::OneMinusSrcAlpha);
    EXPECT_EQ(rgba8.composite.colorTargets[0].blend.dstAlpha, BlendFactor::One);  // the host's alpha kept
    EXPECT_FALSE(rgba8.restoresDepth);

    s.maskPrecision = ssam::MaskPrecision::Rg16f;
    s.depthMaskThreshold = 0.5f;
    const PassPlan rg16f = describePasses(s);
    EXPECT_EQ(rg16f.mask.colorTargetCount, 2);
    EXPECT_EQ(rg16f.mask.colorTargets[0].blend.alphaOp, BlendOp::Max);
    EXPECT_EQ(rg16f.mask.colorTargets[1].blend.colorOp, BlendOp::Add);
    EXPECT_EQ(rg16f.mask.colorTargets[1].format, TargetFormat::R16f);
    EXPECT_TRUE(rg16f.restoresDepth);
    EXPECT_TRUE(rg16f.depthRestore.depthWrite);
    EXPECT_EQ(rg16f.depthRestore.colorTargetCount, 0);
}

}  // namespace
