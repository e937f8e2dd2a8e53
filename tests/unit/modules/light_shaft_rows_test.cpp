// SPDX-License-Identifier: MIT
// The light shafts' wide march (LightShaftKernel::shadeRow, light_shaft_march.inl) against
// the per-pixel shade() it stands for, bit for bit, in every instruction set this CPU runs:
// random depth images (sky, geometry, NaN, both depth conventions), suns on and off the
// screen, with and without a glow radius, any decay (negative ones too: the program takes
// any finite value), and rows whose lanes are partly live.
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "engine/render/soft/simd_isa.hpp"
#include "lcg.hpp"  // tests/support
#include "light_shaft_kernel.hpp"

namespace {

namespace soft = engine::render::soft;
using ssam::testing::Lcg;

soft::SoftTexture depthImage(int w, int h, float farDepth, Lcg& rng) {
    soft::SoftTexture t;
    t.desc.width = w;
    t.desc.height = h;
    t.desc.format = engine::render::Format::D32F;
    t.bytesPerSample = 4;
    t.levels.push_back({w, h, std::vector<std::byte>(std::size_t(w) * std::size_t(h) * 4), {}});
    for (int i = 0; i < w * h; ++i) {
        const float u = rng.unit();
        const float z = u < 0.5f ? farDepth : u < 0.98f ? rng.unit() : std::numeric_limits<float>::quiet_NaN();
        std::memcpy(t.levels[0].texels.data() + 4 * std::size_t(i), &z, 4);
    }
    return t;
}

std::uint32_t bitsOf(float x) { return std::bit_cast<std::uint32_t>(x); }

TEST(LightShaftRows, EveryInstructionSetMarchesTheBitsOfShade) {
    Lcg rng{20261126};
    constexpr int kW = 61, kH = 37;  // rows end in partial blocks
    int rowsChecked = 0, nonZero = 0;
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
        for (soft::SimdIsa isa : soft::supportedSimdIsas()) {
            for (int y = 0; y < kH; ++y) {
                for (int bx = 0; bx < kW; bx += 8) {
                    std::uint32_t live = bx + 8 <= kW ? 0xFFu : (1u << (kW - bx)) - 1u;
                    if ((y + bx) % 3 == 0) live &= std::uint32_t(rng.unit() * 256.0f);  // gaps in the row
                    glm::vec4 out[8];
                    kernel.shadeRow(isa, bx, y, live, out);
                    ++rowsChecked;
                    for (int i = 0; i < 8; ++i) {
                        if (!((live >> i) & 1u)) continue;
                        soft::Fragment f;
                        f.x = bx + i;
                        f.y = y;
                        const glm::vec4 expected = kernel.shade(f);
                        nonZero += expected.r != 0.0f;
                        for (int c = 0; c < 4; ++c)
                            ASSERT_EQ(bitsOf(out[i][c]), bitsOf(expected[c]))
                                << soft::simdIsaName(isa) << ", trial " << trial << ", pixel (" << bx + i << ", "
                                << y << "), channel " << c << ": " << out[i][c] << " != " << expected[c];
                    }
                }
            }
        }
    }
    EXPECT_GT(rowsChecked, 24 * 8 * kH);
    EXPECT_GT(nonZero, 1000) << "too few pixels received light for the comparison to mean much";
}

}  // namespace
