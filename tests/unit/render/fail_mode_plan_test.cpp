// SPDX-License-Identifier: MIT
// The fail-mode emulation plan (no API): which steps each GS fail mode becomes, and which
// combinations are reported inexact. Its input is the resolved alpha test (enabled only where
// it can matter), so whether a test is dropped is resolved_draw_state_test's.
#include <gtest/gtest.h>

#include "engine/render/blend_state.hpp"
#include "engine/render/fail_mode_plan.hpp"

namespace engine::render {
namespace {

FailModeInputs inputs(AlphaFailMode mode, bool test, bool write, CompareFunc func = CompareFunc::Less) {
    FailModeInputs in;
    in.alphaTest = {true, CompareFunc::GreaterEqual, 0.5f, mode, false};
    in.depthTest = test;
    in.depthWrite = write;
    in.depthFunc = func;
    return in;
}

TEST(FailModePlan, OffTestIsOneStepOverAllFragments) {
    FailModeInputs in = inputs(AlphaFailMode::Keep, true, true);
    in.alphaTest.enabled = false;
    FailModePlan plan = planFailMode(in);
    ASSERT_EQ(plan.steps.size(), 1u);
    EXPECT_EQ(plan.steps[0].select, FragmentSelect::All);
    EXPECT_EQ(plan.steps[0].channels, WriteAll);
    EXPECT_TRUE(plan.steps[0].depthWrite);
    in.depthWrite = false;
    plan = planFailMode(in);
    ASSERT_EQ(plan.steps.size(), 1u);
    EXPECT_FALSE(plan.steps[0].depthWrite);
    EXPECT_TRUE(plan.exact);
}

TEST(FailModePlan, KeepIsADiscard) {
    const FailModePlan plan = planFailMode(inputs(AlphaFailMode::Keep, true, true));
    ASSERT_EQ(plan.steps.size(), 1u);
    EXPECT_EQ(plan.steps[0].select, FragmentSelect::Passing);
    EXPECT_EQ(plan.steps[0].channels, WriteAll);
    EXPECT_TRUE(plan.steps[0].depthWrite);
    EXPECT_TRUE(plan.exact);
}

TEST(FailModePlan, ZbOnlyWithoutDepthWritesIsADiscard) {
    const FailModePlan plan = planFailMode(inputs(AlphaFailMode::ZbOnly, true, false));
    ASSERT_EQ(plan.steps.size(), 1u);
    EXPECT_EQ(plan.steps[0].select, FragmentSelect::Passing);
    EXPECT_TRUE(plan.exact);
}

// [PCSX2]: with depth ALWAYS, colour by the fragments that write colour, depth by those
// that write depth, each in primitive order: exact.
TEST(FailModePlan, DepthAlwaysRewrite) {
    FailModePlan plan = planFailMode(inputs(AlphaFailMode::FbOnly, true, true, CompareFunc::Always));
    ASSERT_EQ(plan.steps.size(), 2u);
    EXPECT_EQ(plan.steps[0].select, FragmentSelect::All);
    EXPECT_EQ(plan.steps[0].channels, WriteAll);
    EXPECT_FALSE(plan.steps[0].depthWrite);
    EXPECT_EQ(plan.steps[1].select, FragmentSelect::Passing);
    EXPECT_EQ(plan.steps[1].channels, 0);
    EXPECT_TRUE(plan.steps[1].depthWrite);
    EXPECT_TRUE(plan.exact);

    plan = planFailMode(inputs(AlphaFailMode::ZbOnly, true, true, CompareFunc::Always));
    ASSERT_EQ(plan.steps.size(), 2u);
    EXPECT_EQ(plan.steps[0].select, FragmentSelect::All);
    EXPECT_EQ(plan.steps[0].channels, 0);
    EXPECT_TRUE(plan.steps[0].depthWrite);
    EXPECT_EQ(plan.steps[1].select, FragmentSelect::Passing);
    EXPECT_EQ(plan.steps[1].channels, WriteAll);
    EXPECT_TRUE(plan.exact);
}

TEST(FailModePlan, RgbOnlySplitsColourAndAlpha) {
    FailModeInputs in = inputs(AlphaFailMode::RgbOnly, true, false);
    FailModePlan plan = planFailMode(in);
    ASSERT_EQ(plan.steps.size(), 2u);
    EXPECT_EQ(plan.steps[0].select, FragmentSelect::All);
    EXPECT_EQ(plan.steps[0].channels, WriteRGB);
    EXPECT_EQ(plan.steps[1].select, FragmentSelect::Passing);
    EXPECT_EQ(plan.steps[1].channels, WriteA);
    EXPECT_TRUE(plan.exact);
    in.rgbReadsDstAlpha = true;
    plan = planFailMode(in);
    EXPECT_FALSE(plan.exact);
    EXPECT_NE(plan.note.find("destination alpha"), std::string::npos) << plan.note;
    // Per triangle, the RGB step reads each pixel's alpha before the alpha step writes it.
    in.perTriangleAllowed = true;
    plan = planFailMode(in);
    EXPECT_TRUE(plan.exact);
    EXPECT_TRUE(plan.perTriangle);
}

TEST(FailModePlan, DepthTestedAndWrittenIsTwoPassAndInexact) {
    for (AlphaFailMode mode : {AlphaFailMode::FbOnly, AlphaFailMode::ZbOnly, AlphaFailMode::RgbOnly}) {
        FailModeInputs in = inputs(mode, true, true, CompareFunc::LessEqual);
        FailModePlan plan = planFailMode(in);
        ASSERT_EQ(plan.steps.size(), 2u) << alphaFailModeName(mode);
        EXPECT_EQ(plan.steps[0].select, FragmentSelect::Passing);
        EXPECT_EQ(plan.steps[0].channels, WriteAll);
        EXPECT_TRUE(plan.steps[0].depthWrite);
        EXPECT_EQ(plan.steps[1].select, FragmentSelect::Failing);
        EXPECT_FALSE(plan.exact);
        EXPECT_NE(plan.note.find(alphaFailModeName(mode)), std::string::npos) << plan.note;
        EXPECT_FALSE(plan.perTriangle);
        in.perTriangleAllowed = true;
        plan = planFailMode(in);
        EXPECT_TRUE(plan.exact);
        EXPECT_TRUE(plan.perTriangle);
    }
    const FailModePlan zb = planFailMode(inputs(AlphaFailMode::ZbOnly, true, true));
    EXPECT_EQ(zb.steps[1].channels, 0);
    EXPECT_TRUE(zb.steps[1].depthWrite);
    const FailModePlan rgb = planFailMode(inputs(AlphaFailMode::RgbOnly, true, true));
    EXPECT_EQ(rgb.steps[1].channels, WriteRGB);
    EXPECT_FALSE(rgb.steps[1].depthWrite);
}

}  // namespace
}  // namespace engine::render
