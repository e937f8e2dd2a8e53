// SPDX-License-Identifier: MIT
// The particle layer composite's row hook (LayerCompositeKernel::shadeRow, particle_kernels.hpp)
// against the per-pixel shade() it stands for, bit for bit: half-resolution RGBA16F layers that
// are mostly or nearly all empty (all-zero texels, the case the hook answers without decoding,
// a whole row at once where it can) with puffs,
// +-0 and NaN texels, random scene depth, both depth conventions, full-resolution layers, and
// rows whose lanes are partly live.
#include <cstring>
#include <limits>

#include <gtest/gtest.h>

#include "engine/render/pixel_codec.hpp"
#include "lcg.hpp"  // tests/support
#include "particle_kernels.hpp"
#include "row_hook_check.hpp"  // tests/support
#include "soft_image.hpp"      // tests/support

namespace {

namespace soft = engine::render::soft;
using engine::render::Format;
using ssam::testing::Lcg;

// Zero bits in `empty` of the texels; the others a puff colour, -0 or NaN.
soft::SoftTexture layerImage(int w, int h, float empty, Lcg& rng) {
    soft::SoftTexture t = ssam::testing::softImage(w, h, Format::RGBA16F, 8);
    for (int i = 0; i < w * h; ++i) {
        if (rng.unit() < empty) continue;
        const float u = 0.7f + 0.3f * rng.unit();
        std::uint16_t half[4];
        for (int c = 0; c < 4; ++c) {
            const float v = u < 0.9f ? rng.unit() : u < 0.95f ? -0.0f : std::numeric_limits<float>::quiet_NaN();
            half[c] = engine::render::encodeHalf(v);
        }
        std::memcpy(t.levels[0].texels.data() + 8 * std::size_t(i), half, sizeof half);
    }
    return t;
}

TEST(LayerCompositeRows, RowHookShadesTheBitsOfShade) {
    Lcg rng{20261127};
    constexpr int kW = 61, kH = 37;  // rows end in partial blocks
    int zeros = 0, others = 0;
    for (int trial = 0; trial < 24; ++trial) {
        const int scale = trial % 3 == 2 ? 1 : 2;
        // Every other layer nearly empty: most block rows then read no written texel, and the
        // hook answers them whole (layerZeroUnderRow), a lone puff at the edge of a row's run
        // included.
        const float empty = trial % 4 < 2 ? 0.7f : 0.98f;
        const soft::SoftTexture layer = layerImage((kW + scale - 1) / scale, (kH + scale - 1) / scale, empty, rng);
        const soft::SoftTexture depth =
            ssam::testing::depthImage(kW, kH, [&](int) { return 0.05f + 0.9f * rng.unit(); });
        particles::LayerCompositeParams params;
        params.layerScale = scale;
        params.depthScale = 0.1f;
        params.depthOffset = trial % 2 ? -1.0f : 0.0f;
        params.greaterIsCloser = trial % 2 == 1;
        struct Textures final : soft::TextureLookup {
            const soft::SoftTexture *layer, *depth;
            Textures(const soft::SoftTexture* l, const soft::SoftTexture* d) : layer(l), depth(d) {}
            const soft::SoftTexture* texture(engine::render::TextureHandle h) const override {
                return h.index == 1 ? layer : depth;
            }
        };
        params.layer = {1, 1};
        params.sceneDepth = {2, 1};
        const particles::LayerCompositeKernel kernel(params, Textures(&layer, &depth));
        ASSERT_TRUE(ssam::testing::rowHookMatchesShade(
            kernel, soft::SimdIsa::Sse2, kW, kH, rng,
            [&](const glm::vec4& e) { (e == glm::vec4(0.0f) ? zeros : others) += 1; }))
            << "trial " << trial;
    }
    // Both kinds of pixel occur often enough for the comparison to mean something.
    EXPECT_GT(zeros, 1000);
    EXPECT_GT(others, 1000);
}

}  // namespace
