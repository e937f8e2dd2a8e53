// SPDX-License-Identifier: MIT
// The fail-mode emulation plan (no API): which steps each GS fail mode becomes, and which
// combinations are reported inexact. Its input is the resolved alpha test (enabled only where
// it can matter), so whether a test is dropped is resolved_draw_state_test's.
#include <gtest/gtest.h>

#include <tuple>
#include <utility>
#include <vector>

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

// A plan step as (select, channels, depthWrite): one expectation compares a whole plan and
// prints it when it differs.
using Step = std::tuple<FragmentSelect, int, bool>;

std::vector<Step> steps(const FailModePlan& plan) {
    std::vector<Step> out;
    for (const PlanStep& s : plan.steps) out.emplace_back(s.select, s.channels, s.depthWrite);
    return out;
}

TEST(FailModePlan, OffTestIsOneStepOverAllFragments) {
    FailModeInputs in = inputs(AlphaFailMode::Keep, true, true);
    in.alphaTest.enabled = false;
    EXPECT_EQ(steps(planFailMode(in)), (std::vector<Step>{{FragmentSelect::All, WriteAll, true}}));
    in.depthWrite = false;
    const FailModePlan plan = planFailMode(in);
    EXPECT_EQ(steps(plan), (std::vector<Step>{{FragmentSelect::All, WriteAll, false}}));
    EXPECT_TRUE(plan.exact);
}

TEST(FailModePlan, KeepIsADiscard) {
    const FailModePlan plan = planFailMode(inputs(AlphaFailMode::Keep, true, true));
    EXPECT_EQ(steps(plan), (std::vector<Step>{{FragmentSelect::Passing, WriteAll, true}}));
    EXPECT_TRUE(plan.exact);
}

TEST(FailModePlan, ZbOnlyWithoutDepthWritesIsADiscard) {
    const FailModePlan plan = planFailMode(inputs(AlphaFailMode::ZbOnly, true, false));
    EXPECT_EQ(steps(plan), (std::vector<Step>{{FragmentSelect::Passing, WriteAll, false}}));
    EXPECT_TRUE(plan.exact);
}

// [PCSX2]: with depth ALWAYS, colour by the fragments that write colour, depth by those
// that write depth, each in primitive order: exact.
TEST(FailModePlan, DepthAlwaysRewrite) {
    FailModePlan plan = planFailMode(inputs(AlphaFailMode::FbOnly, true, true, CompareFunc::Always));
    EXPECT_EQ(steps(plan),
              (std::vector<Step>{{FragmentSelect::All, WriteAll, false}, {FragmentSelect::Passing, 0, true}}));
    EXPECT_TRUE(plan.exact);

    plan = planFailMode(inputs(AlphaFailMode::ZbOnly, true, true, CompareFunc::Always));
    EXPECT_EQ(steps(plan),
              (std::vector<Step>{{FragmentSelect::All, 0, true}, {FragmentSelect::Passing, WriteAll, false}}));
    EXPECT_TRUE(plan.exact);
}

TEST(FailModePlan, RgbOnlySplitsColourAndAlpha) {
    FailModeInputs in = inputs(AlphaFailMode::RgbOnly, true, false);
    FailModePlan plan = planFailMode(in);
    EXPECT_EQ(steps(plan),
              (std::vector<Step>{{FragmentSelect::All, WriteRGB, false}, {FragmentSelect::Passing, WriteA, false}}));
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
    // Each mode's failing fragments write what the mode keeps: everything, depth only, RGB only.
    const std::pair<AlphaFailMode, Step> failingSteps[] = {
        {AlphaFailMode::FbOnly, {FragmentSelect::Failing, WriteAll, false}},
        {AlphaFailMode::ZbOnly, {FragmentSelect::Failing, 0, true}},
        {AlphaFailMode::RgbOnly, {FragmentSelect::Failing, WriteRGB, false}}};
    for (const auto& [mode, failing] : failingSteps) {
        FailModeInputs in = inputs(mode, true, true, CompareFunc::LessEqual);
        FailModePlan plan = planFailMode(in);
        EXPECT_EQ(steps(plan), (std::vector<Step>{{FragmentSelect::Passing, WriteAll, true}, failing}))
            << alphaFailModeName(mode);
        EXPECT_FALSE(plan.exact);
        EXPECT_NE(plan.note.find(alphaFailModeName(mode)), std::string::npos) << plan.note;
        EXPECT_FALSE(plan.perTriangle);
        in.perTriangleAllowed = true;
        plan = planFailMode(in);
        EXPECT_TRUE(plan.exact);
        EXPECT_TRUE(plan.perTriangle);
    }
}

}  // namespace
}  // namespace engine::render
