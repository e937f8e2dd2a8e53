// SPDX-License-Identifier: MIT
#include "engine/render/fail_mode_plan.hpp"

#include "engine/render/blend_state.hpp"

namespace engine::render {

namespace {

// What a fragment class writes: ColorWrite bits plus kDepthBit.
constexpr std::uint8_t kDepthBit = 0x10;

std::uint8_t failWrites(AlphaFailMode mode, bool depthWrite) {
    switch (mode) {
        case AlphaFailMode::Keep: return 0;
        case AlphaFailMode::FbOnly: return WriteAll;
        case AlphaFailMode::ZbOnly: return depthWrite ? kDepthBit : 0;
        case AlphaFailMode::RgbOnly: return WriteRGB;
    }
    return 0;
}

PlanStep step(FragmentSelect select, std::uint8_t writes) {
    return {select, std::uint8_t(writes & WriteAll), (writes & kDepthBit) != 0};
}

}  // namespace

FailModePlan planFailMode(const FailModeInputs& in) {
    FailModePlan plan;
    const bool depthWrite = in.depthTest && in.depthWrite;
    const std::uint8_t passWrites = std::uint8_t(WriteAll | (depthWrite ? kDepthBit : 0));
    const AlphaTest& test = in.alphaTest;

    if (!test.enabled) {  // off, or dropped by the resolver: it cannot change the result
        plan.steps.push_back(step(FragmentSelect::All, passWrites));
        return plan;
    }
    const std::uint8_t fail = failWrites(test.failMode, depthWrite);
    if (fail == 0) {  // KEEP, or ZB_ONLY without depth writes: a plain discard
        plan.steps.push_back(step(FragmentSelect::Passing, passWrites));
        return plan;
    }

    const bool depthStatic = !depthWrite || in.depthFunc == CompareFunc::Always || in.depthFunc == CompareFunc::Never;
    if (depthStatic) {
        // One step per fragment subset: attributes written by both classes go to an All step,
        // those written by passing fragments only to a Passing step (fail writes are a subset
        // of pass writes). RGB-carrying steps first.
        const std::uint8_t both = passWrites & fail;
        const std::uint8_t passOnly = passWrites & std::uint8_t(~fail);
        if (both) plan.steps.push_back(step(FragmentSelect::All, both));
        if (passOnly) plan.steps.push_back(step(FragmentSelect::Passing, passOnly));
        if (depthWrite) plan.note = "[PCSX2] depth-always rewrite: one step per fragment subset";
        else plan.note = "no depth writes: one step per fragment subset";
        const bool rgbAlphaSplit = (both & WriteRGB) && (passOnly & WriteA);
        if (rgbAlphaSplit && in.rgbReadsDstAlpha && in.anyAlphaWrite) {
            if (in.perTriangleAllowed) {  // within a triangle the RGB step reads alpha before the A step
                plan.perTriangle = true;
                plan.note = "RGB and alpha steps per triangle: exact";
                return plan;
            }
            plan.exact = false;
            plan.note = std::string(alphaFailModeName(test.failMode)) +
                        ": RGB (all fragments) and alpha (passing fragments) are written in separate steps, "
                        "so RGB blend factors reading destination alpha see it early where fragments of one "
                        "draw overlap";
        }
        return plan;
    }

    // Depth tested and written: passing fragments, then failing ones.
    plan.steps.push_back(step(FragmentSelect::Passing, passWrites));
    plan.steps.push_back(step(FragmentSelect::Failing, fail));
    if (in.perTriangleAllowed) {
        plan.perTriangle = true;
        plan.note = "two steps per triangle: exact (a triangle's fragments never overlap)";
    } else {
        plan.exact = false;
        plan.note = std::string(alphaFailModeName(test.failMode)) + " with depth test " +
                    compareFuncName(in.depthFunc) +
                    " and depth writes: two-pass split (passing, then failing fragments, [PCSX2]) is "
                    "inexact where fragments of one draw overlap";
    }
    return plan;
}

}  // namespace engine::render
