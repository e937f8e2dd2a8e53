// SPDX-License-Identifier: MIT
// The light shafts' wide march (LightShaftKernel::shadeRow, light_shaft_march.inl) against
// the per-pixel shade() it stands for, bit for bit, in every instruction set this CPU runs:
// random depth images (sky, geometry, NaN, both depth conventions), suns on and off the
// screen, with and without a glow radius, any decay (negative ones too: the program takes
// any finite value), and rows whose lanes are partly live.
#include <cmath>
#include <cstring>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "engine/render/kernel/simd_isa.hpp"
#include "lcg.hpp"  // tests/support
#include "light_shaft_kernel.hpp"
#include "row_hook_check.hpp"  // tests/support
#include "soft_image.hpp"      // tests/support

namespace {

namespace soft = engine::render::soft;
using ssam::testing::Lcg;

// Half sky, most of the rest geometry at random depths, some NaN.
soft::SoftTexture depthImage(int w, int h, float farDepth, Lcg& rng) {
    return ssam::testing::depthImage(w, h, [&](int) {
        const float u = rng.unit();
        return u < 0.5f ? farDepth : u < 0.98f ? rng.unit() : std::numeric_limits<float>::quiet_NaN();
    });
}

TEST(LightShaftRows, EveryInstructionSetMarchesTheBitsOfShade) {
    Lcg rng{20261126};
    constexpr int kW = 61, kH = 37;  // rows end in partial blocks
    int nonZero = 0;
    for (int trial = 0; trial < 24; ++trial) {
        lightshafts::LightShaftParams params;
        params.greaterIsCloser = trial % 2 == 1;
        params.farDepth = params.greaterIsCloser ? 0.0f : 1.0f;
        params.sunPixel = {rng.unit() * 1.6f * kW - 0.3f * kW, rng.unit() * 1.6f * kH - 0.3f * kH};
        params.decay = trial % 5 == 4 ? -0.9f : 0.9f + 0.1f * rng.unit();
        params.density = 0.2f + 0.8f * rng.unit();
        params.samples = 1 + int(rng.unit() * 80.0f);
        params.glowRadius = trial % 3 == 0 ? 0.0f : 4.0f + 30.0f * rng.unit();
        params.intensity = 0.5f;
        const soft::SoftTexture depth = depthImage(kW, kH, params.farDepth, rng);
        struct OneTexture final : soft::TextureLookup {
            const soft::SoftTexture* depth;
            explicit OneTexture(const soft::SoftTexture* d) : depth(d) {}
            const soft::SoftTexture* texture(engine::render::TextureHandle) const override { return depth; }
        };
        const lightshafts::LightShaftKernel kernel(params, OneTexture(&depth));
        for (soft::SimdIsa isa : soft::supportedSimdIsas())
            ASSERT_TRUE(ssam::testing::rowHookMatchesShade(kernel, isa, kW, kH, rng,
                                                           [&](const glm::vec4& e) { nonZero += e.r != 0.0f; }))
                << "trial " << trial;
    }
    EXPECT_GT(nonZero, 1000) << "too few pixels received light for the comparison to mean much";
}

}  // namespace
