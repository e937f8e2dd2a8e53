// SPDX-License-Identifier: MIT
#pragma once
// How a backend without fail modes of its own (GL: only `discard`) turns a GS-style alpha test
// ([PCSX2]) into draws: a list of steps, each drawing the whole draw with the fragments that
// pass, fail or all of them, writing only some channels and maybe depth. Pure logic, no API,
// so it is unit-tested on its own; the draw-state resolver (resolved_draw_state.hpp) makes the
// plan, drivers only issue its steps.
//
// Which fragments write what (soft backend, tile_rasterizer.cpp):
//   pass: RGB, A, Z          fail: KEEP -, FB_ONLY RGB A, ZB_ONLY Z, RGB_ONLY RGB
// When the depth buffer cannot change the outcome of the depth test during the draw (no
// depth writes, or depth func ALWAYS/NEVER), each of RGB, A and Z is a sequence of writes by
// a fixed fragment subset in primitive order, so one step per subset is exact (for ALWAYS
// this is the seed's "depth-always rewrite"). One exception: RGB_ONLY's RGB (all fragments)
// and A (passing) land in different steps, so RGB blend factors that read destination alpha
// see it one step early where fragments overlap: inexact, reported.
// When depth is tested and written (LESS etc.), which fragment wins depends on the order of
// passing and failing fragments: the two-pass split (passing, then failing) is inexact where
// fragments of one draw overlap, whatever the blending; per-triangle steps are exact.
#include <cstdint>
#include <string>
#include <vector>

#include "engine/render/alpha_test.hpp"
#include "engine/render/depth_state.hpp"

namespace engine::render {

enum class FragmentSelect : std::uint8_t { All, Passing, Failing };

struct PlanStep {
    FragmentSelect select = FragmentSelect::All;
    std::uint8_t channels = 0xF;  // ColorWrite bits this step may write (ANDed with each target's mask)
    bool depthWrite = false;
};

struct FailModePlan {
    std::vector<PlanStep> steps;
    bool perTriangle = false;  // issue the steps triangle by triangle
    bool exact = true;
    std::string note;  // how it was emulated / why it is inexact
};

struct FailModeInputs {
    AlphaTest alphaTest;  // effective: enabled only where it can change the result (the resolver's rule)
    bool depthTest = false;
    bool depthWrite = false;  // effective: only with the test on
    CompareFunc depthFunc = CompareFunc::Less;
    bool anyRgbWrite = true;
    bool anyAlphaWrite = true;
    bool rgbReadsDstAlpha = false;    // some blending target's RGB factors use destination alpha
    bool perTriangleAllowed = false;  // FailModeEmulation::PerTriangle
};

FailModePlan planFailMode(const FailModeInputs& in);

}  // namespace engine::render
