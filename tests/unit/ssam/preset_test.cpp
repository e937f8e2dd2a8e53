// SPDX-License-Identifier: MIT
// ssam::Preset: `paper` is exactly Config{} (the paper's values, as config.hpp promises), `measured`
// differs from it only in the knobs ssam/docs/knobs.md chose it by, and names round-trip.
#include <gtest/gtest.h>

#include "ssam/preset.hpp"

namespace {

void expectSameKnobs(const ssam::Config& a, const ssam::Config& b) {
    EXPECT_EQ(a.maskLerp, b.maskLerp);
    EXPECT_EQ(a.colorAlphaReference, b.colorAlphaReference);
    EXPECT_EQ(a.foliageClearColor, b.foliageClearColor);
    EXPECT_EQ(a.squareMask, b.squareMask);
    EXPECT_EQ(a.maskPrecision, b.maskPrecision);
    EXPECT_EQ(a.depthFunc, b.depthFunc);
}

TEST(SsamPreset, PaperIsTheDefaultConfig) { expectSameKnobs(ssam::presetConfig(ssam::Preset::Paper), ssam::Config{}); }

TEST(SsamPreset, MeasuredChangesOnlyTheMaskKnobsAndIsValid) {
    const ssam::Config paper;
    const ssam::Config measured = ssam::presetConfig(ssam::Preset::Measured);
    EXPECT_NO_THROW(measured.validate());
    EXPECT_FALSE(measured.squareMask);  // §3.6.2's trick off: the bias knobs.md measured
    EXPECT_EQ(measured.maskLerp, 0.9f);
    EXPECT_EQ(measured.colorAlphaReference, 96.0f / 255.0f);
    // The cost knob stays the paper's: a float mask costs +46% on soft (knobs.md), over the 1.25x budget.
    EXPECT_EQ(measured.maskPrecision, paper.maskPrecision);
    EXPECT_EQ(measured.foliageClearColor, paper.foliageClearColor);
    EXPECT_EQ(measured.depthFunc, paper.depthFunc);
}

TEST(SsamPreset, NamesRoundTripAndUnknownNamesAreRefused) {
    for (ssam::Preset p : {ssam::Preset::Paper, ssam::Preset::Measured})
        EXPECT_EQ(ssam::parsePreset(ssam::presetName(p)), p);
    EXPECT_EQ(std::string(ssam::presetName(ssam::Preset::Paper)), "paper");
    EXPECT_EQ(std::string(ssam::presetName(ssam::Preset::Measured)), "measured");
    EXPECT_FALSE(ssam::parsePreset("Paper").has_value());
    EXPECT_FALSE(ssam::parsePreset("").has_value());
    EXPECT_EQ(ssam::kRecommendedPreset, ssam::Preset::Measured);
}

}  // namespace
