// SPDX-License-Identifier: MIT
#pragma once
// Differential scenes: the same random scenes on the soft backend (the reference) and a GPU
// backend (GL: gl_differential; Vulkan: vk_differential), compared target by target, pixel by
// pixel, with one set of tolerances. lavapipe (Vulkan) is llvmpipe's rasterizer and shader
// compiler behind Vulkan, so what is said of llvmpipe below holds for both; the Vulkan
// specification leaves open what GL 4.5 leaves open here (blend precision, rounding to half,
// the rule for a sample exactly on an edge, the precision of the sRGB conversions).
//
// A scene is an SSAM-shaped frame: an opaque pass (Flat and OpaqueLit, textured with every
// filter and address mode, instanced, culled, scissored), the foliage mask pass (AlphaOnly,
// SSAM mask blend RGB MAX + A ADD), the foliage colour pass (MaskedLit, alpha-tested,
// depth-writing), the composite (full-screen, SRC_ALPHA / INV_SRC_ALPHA), and a "zoo" pass in its
// own target: Flat triangles with random blend factors, ops, constants, write masks, depth
// functions and GS alpha tests (every function and fail mode). Colour targets are RGBA8, sRGB,
// RGBA16F or RGBA32F, single-sampled or 4x MSAA (resolved: colour average, closest depth); the
// fail modes run with the default two-pass emulation (draws the backend reports inexact are left
// out of both runs) and with the exact per-triangle one (nothing left out).
//
// Geometry is built so that rasterization is identical wherever the GL spec lets it be:
//   - vertices land on the 1/256-pixel grid (x/w and y/w exact), inside the target, so both
//     backends snap them to the same 8-bit sub-pixel positions and nothing is clipped (GL clips
//     with new vertices off the grid; clipping is the clipping suite's); per-vertex w is 1, 2
//     or 4, so perspective-correct interpolation is exercised while the divide stays exact;
//   - each draw has one constant depth (z = depth * w), 1/64 from every other draw's, so depth
//     tests never hinge on interpolation rounding (equal-depth draws test EQUAL/LEQUAL exactly);
//   - with 4x MSAA (standard sample positions on both), no edge passes through a sample: GL
//     leaves the rule for a sample exactly on an edge open and llvmpipe's is not top-left there;
//   - alpha-tested values stay at least 0.08 from the reference (no interpolation rounding
//     decides a fragment), alpha-tested textures are sampled with Nearest.
// Coverage then matches exactly: no tolerance below allows for a pixel covered by one backend only.
//
// Tolerances per stored value, and why:
//   UNORM: 2 codes (values beyond 1 code come from blending; their count is printed). GL lets blending run at the destination's precision (GL 4.5
//     §17.3.6): llvmpipe quantizes the source to 8 bits and multiplies in 8-bit fixed point; its
//     float-to-UNORM conversion rounds ties to even where the soft backend rounds them up.
//   sRGB: as UNORM, or within 2/255 in linear light: llvmpipe's sRGB decode/encode are
//     approximations, and near black the curve's slope (up to 12.92) turns small linear
//     differences into several codes.
//   RGBA16F: 4 half ULPs at the scale of max(|value|, 1): llvmpipe rounds float-to-half toward
//     zero (the soft backend to nearest even; GL leaves it open), once per store, so the SSAM
//     mask's ADD over several layers accumulates, and blends of operands near 1 cancel.
//   RGBA32F: 1e-5 relative to max(|value|, 1): interpolation planes are set up in float by
//     llvmpipe, in double by the soft backend; log2/pow approximations in the shader.
//   D32F: 1e-6 absolute.
// What the scenes avoid because the result would not say anything about the backend: sRGB
// textures sampled into float targets (llvmpipe's sRGB decode is within 7.3e-4), UNORM
// textures filtered into float targets (llvmpipe filters 8-bit textures with 8-bit weights, an
// error up to |t1 - t0| / 512; GL leaves weight precision open); the SSAM intermediates are
// RGBA32F when the colour target is (a composite of inputs a few half ULPs apart cannot agree
#include <ostream>
#include <string>
#include <vector>

#include "engine/render/backend.hpp"
#include "engine/render/format.hpp"

namespace ssam::test::differential {

struct Case {
    engine::render::Format format;
    int samples;
    bool perTriangle;  // the fail modes' exact per-triangle emulation, else the two-pass one
};

// The cases both backends run (formats, 1x and 4x, both fail-mode strategies).
std::vector<Case> cases();

// "RGBA8_UNORM_x1_twoPass": the test's parameter name.
std::string caseName(const Case& c);
inline void PrintTo(const Case& c, std::ostream* os) { *os << caseName(c); }  // GoogleTest's parameter print

// Runs three random scenes of the case on `backend` and on a soft backend and adds a GoogleTest
// failure for every value beyond the tolerances above (the first 8 per target, naming `name`).
// Draws `backend` reports inexact (pipelineInfo) are left out of both runs.
void expectRandomScenesMatchSoft(engine::render::Backend& backend, const char* name, const Case& c);

}  // namespace ssam::test::differential
