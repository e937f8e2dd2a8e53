// SPDX-License-Identifier: MIT
#pragma once
// The state a draw really has, resolved once from its pipeline and its pass's targets by the
// render front end. Every rule that turns what a pipeline asks for into what a draw does lives
// here: the write masks a target's format allows, whether blending is needed, whether the
// alpha test can change anything and how its fail modes are emulated, depth test and write,
// alpha-to-coverage, the clamped scissor. Drivers (soft, GL, ...) translate the result into
// their own terms and derive none of it again, so a new state bit is one edit here.
#include <array>
#include <cstdint>
#include <optional>

#include <glm/glm.hpp>

#include "engine/render/alpha_test.hpp"
#include "engine/render/backend.hpp"
#include "engine/render/blend_state.hpp"
#include "engine/render/fail_mode_plan.hpp"
#include "engine/render/format.hpp"
#include "engine/render/pipeline.hpp"
#include "engine/render/raster_state.hpp"

namespace engine::render {

// How a driver carries out the alpha test's fail modes ([PCSX2] "Looking further").
enum class FailModeEmulation : std::uint8_t {
    None,         // the driver does them itself (soft): no plan is made
    TwoPass,      // steps over the whole draw (FailModePlan)
    PerTriangle,  // steps triangle by triangle where that is what makes them exact
};

// What a pass binds, as its draws see it: colour targets packed in attachment order.
struct DrawTargets {
    std::array<Format, kMaxColorTargets> colorFormats{};
    int colorTargetCount = 0;
    bool hasDepth = false;
    int samples = 1;
    int width = 0;
    int height = 0;
};

struct ResolvedDrawState {
    int colorTargetCount = 0;
    // The pipeline's blending per packed target, its write mask cut to the channels the
    // target's format has (a channel the format lacks is never written).
    std::array<BlendState, kMaxColorTargets> blend{};
    std::array<bool, kMaxColorTargets> blendNeeded{};  // false: a plain store (isPlainWrite)
    glm::vec4 blendConstant{0.0f};
    bool anyRgbWrite = false;
    bool anyAlphaWrite = false;
    bool rgbReadsDstAlpha = false;  // some blending target's RGB factors read destination alpha

    bool depthTest = false;   // asked for and a depth target is bound
    bool depthWrite = false;  // only with the test
    CompareFunc depthFunc = CompareFunc::Less;

    AlphaTest alphaTest;            // enabled only where it can change what the draw writes
    bool alphaTestDropped = false;  // asked for, but it cannot (alphaTestCanMatter)
    bool alphaToCoverage = false;   // asked for and the pass has more than one sample
    bool shade = true;              // false: depth only, the program need not run
    Rect scissor;                   // the draw's scissor within the targets; empty: nothing drawn
    FailModePlan failModes;         // empty unless asked for (FailModeEmulation)
};

ResolvedDrawState resolveDrawState(const PipelineDesc& pipeline, const DrawTargets& targets,
                                   const std::optional<Rect>& scissor, FailModeEmulation emulation);

// What can be said of a pipeline before any pass: as resolveDrawState for targets that have
// every channel and a depth buffer. `failModes` is the plan the driver's emulation makes.
struct ResolvedPipeline {
    PipelineInfo info;
    FailModePlan failModes;  // empty for FailModeEmulation::None
};
ResolvedPipeline resolvePipeline(const PipelineDesc& pipeline, FailModeEmulation emulation);

// The rules themselves, exposed for their tests.
// Whether the test can change what a draw writes: only when a failing fragment writes
// something different from a passing one ([PCSX2] "Looking further").
bool alphaTestCanMatter(const AlphaTest& test, bool depthWrite, bool anyRgbWrite, bool anyAlphaWrite);
// Blending whose RGB result depends on the destination alpha: a fail-mode split that writes
// RGB and alpha in separate steps is inexact for it.
bool rgbReadsDstAlpha(const BlendState& blend);
// The draw's scissor (none: the whole target) clamped to a width x height target.
Rect clampScissor(const std::optional<Rect>& scissor, int width, int height);

}  // namespace engine::render
