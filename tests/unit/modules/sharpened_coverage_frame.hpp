// SPDX-License-Identifier: MIT
#pragma once
// SharpenedCoverageLit drawn straight into a float target, for its soft and GPU tests: a
// screen-filling card whose texture is an alpha ramp of 8 texels magnified bilinearly to 64
// pixels, so that alpha changes by 1/56 per pixel across the card (flat within none) and
// crosses the reference once. The output alpha is the sharpened alpha itself.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include "engine/render/backend.hpp"
#include "engine/render/program.hpp"
#include "program_card.hpp"
#include "run_technique.hpp"  // cardVertices
#include "transparency/sharpened_coverage.hpp"

namespace transparency::testing {

inline constexpr int kRampPixels = 64, kRampTexels = 8;

// The ramp's alpha at texel i: i / 7 of 255, rounded.
inline std::uint8_t rampTexelAlpha(int i) { return std::uint8_t((255 * i + 3) / (kRampTexels - 1)); }

inline engine::render::Readback drawSharpenedRamp(engine::render::Backend& backend, float reference) {
    using namespace engine::render;
    std::vector<std::uint8_t> texels;
    for (int i = 0; i < kRampTexels; ++i) texels.insert(texels.end(), {255, 255, 255, rampTexelAlpha(i)});
    const TextureData data{{std::as_bytes(std::span(texels))}};
    const TextureHandle ramp = backend.createTexture({"ramp", kRampTexels, 1, Format::RGBA8_UNORM}, &data);
    const glm::vec3 corners[4] = {{-1, -1, 0.5f}, {1, -1, 0.5f}, {1, 1, 0.5f}, {-1, 1, 0.5f}};
    const std::vector<Vertex> vertices = test_support::cardVertices(corners, 1.0f, glm::vec4(1.0f));
    SharpenedCoverageParams params;
    params.baseColor = {ramp, {Filter::Bilinear, AddressMode::Clamp, AddressMode::Clamp}};
    params.light = unlitLight();
    params.reference = reference;
    // A refused draw throws past the destroys: the tests that expect it make a backend for it.
    Readback r = test_support::drawProgramCard(backend, sharpenedCoverageLitProgram(), params, vertices, kRampPixels);
    backend.destroy(ramp);
    return r;
}

// The ramp's alpha at pixel column x, as the bilinear filter gives it (clamped at both ends).
inline float rampAlpha(int x) {
    const float t =
        std::clamp((float(x) + 0.5f) * float(kRampTexels) / float(kRampPixels) - 0.5f, 0.0f, float(kRampTexels - 1));
    const int i = std::min(int(t), kRampTexels - 2);
    return ((1.0f - (t - float(i))) * float(rampTexelAlpha(i)) + (t - float(i)) * float(rampTexelAlpha(i + 1))) /
           255.0f;
}

// Every pixel of a drawSharpenedRamp readback against [Golus 2017]'s formula evaluated on the
// ramp in float, the width from the pixel's quad partner in x (the ramp is flat in y); within
// `tolerance` for the filter's rounding. Returns how many pixels are strictly between 0 and 1.
inline int expectSharpenedRamp(const engine::render::Readback& r, float reference, float tolerance) {
    int partial = 0;
    for (int x = 0; x < kRampPixels; ++x) {
        const float width = std::abs(rampAlpha(x ^ 1) - rampAlpha(x));
        const float expected = sharpenedCoverage(rampAlpha(x), width, reference);
        for (int y = 0; y < kRampPixels; ++y) {
            const float got = r.at(x, y, 3);
            EXPECT_NEAR(got, expected, tolerance) << "pixel " << x << ", " << y;
            partial += (y == 0 && got > 0.0f && got < 1.0f);
        }
    }
    return partial;
}

}  // namespace transparency::testing
