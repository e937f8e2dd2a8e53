// SPDX-License-Identifier: MIT
// SSAM's composite on the soft backend (CompositeKernel, ssam/src/composite_kernel.hpp): with
// Settings::colorBlur the 8-bit fast path takes its colours from compositeColorRow, which must be
// shade()'s bit for bit (the general path's, which a float target still takes), over random sRGB
// 8-bit and float foliage with unwritten texels, image borders and partly live rows. Without
// colorBlur the fast path reads the texel itself; with colorFade there is no fast path. The
// factors of a block row at once (compositeFactorRow) are compositeFactor's.
#include <bit>
#include <cstdint>
#include <cstring>

#include <gtest/gtest.h>

#include "composite_kernel.hpp"  // ssam/src
#include "lcg.hpp"               // tests/support
#include "row_hook_check.hpp"    // tests/support
#include "soft_image.hpp"        // tests/support

namespace {

namespace soft = engine::render::soft;
using engine::render::Format;
using ssam::testing::Lcg;

// Random texels; a third with alpha 0 (nothing written there).
soft::SoftTexture randomFoliage(int w, int h, Format format, Lcg& rng) {
    const int bytes = format == Format::RGBA8_SRGB ? 4 : 16;
    soft::SoftTexture t = ssam::testing::softImage(w, h, format, bytes);
    for (int i = 0; i < w * h; ++i) {
        std::byte* texel = t.levels[0].texels.data() + std::size_t(bytes) * std::size_t(i);
        const bool unwritten = rng.unit() < 0.3f;
        for (int c = 0; c < 4; ++c) {
            const float v = unwritten && c == 3 ? 0.0f : rng.unit();
            if (bytes == 4) texel[c] = std::byte(std::uint8_t(v * 255.0f));
            else std::memcpy(texel + 4 * c, &v, sizeof v);
        }
    }
    return t;
}

struct Textures final : soft::TextureLookup {
    const soft::SoftTexture *foliage, *mask;
    Textures(const soft::SoftTexture* f, const soft::SoftTexture* m) : foliage(f), mask(m) {}
    const soft::SoftTexture* texture(engine::render::TextureHandle h) const override {
        return !h ? nullptr : h.index == 1 ? foliage : mask;
    }
};

TEST(CompositeRows, BlurredColourRowIsShadesColourBitForBit) {
    Lcg rng{20261207};
    constexpr int kW = 37, kH = 19;  // rows end in partial blocks
    for (Format format : {Format::RGBA8_SRGB, Format::RGBA32F}) {
        const soft::SoftTexture foliage = randomFoliage(kW, kH, format, rng);
        const soft::SoftTexture mask = randomFoliage(kW, kH, Format::RGBA8_SRGB, rng);
        ssam::CompositeParams params;
        params.foliage = {1, 1};
        params.mask = {2, 1};
        params.colorBlur = true;
        const ssam::CompositeKernel kernel(params, Textures(&foliage, &mask));
        EXPECT_EQ(kernel.compositeColor(), &foliage);
        EXPECT_TRUE(ssam::testing::compositeColorRowMatchesShade(kernel, kW, kH, rng))
            << engine::render::formatName(format);
    }
}

// compositeFactorRow (the factors of a block row at once) against compositeFactor, bit for bit,
// over every MAX and ADD byte pair and the lerps and squaring the settings allow; it declines a
// row that leaves the mask and a split mask (RG16F precision), which compositeFactor reads.
TEST(CompositeRows, FactorRowIsCompositeFactorBitForBit) {
    constexpr int kW = 256 + 5, kH = 256;
    soft::SoftTexture mask = ssam::testing::softImage(kW, kH, Format::RGBA8_UNORM, 4);
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) {
            std::byte* t = mask.levels[0].texels.data() + 4 * (std::size_t(y) * kW + std::size_t(x));
            t[0] = std::byte(std::uint8_t(x));  // MAX: every byte along a row
            t[1] = t[2] = std::byte{0x5A};
            t[3] = std::byte(std::uint8_t(y));  // ADD: every byte down a column
        }
    for (const float lerp : {0.0f, 0.37f, 0.85f, 0.9f, 1.0f})
        for (const bool square : {false, true}) {
            ssam::CompositeParams params;
            params.foliage = {1, 1};
            params.mask = {2, 1};
            params.maskLerp = lerp;
            params.squareMask = square;
            const ssam::CompositeKernel kernel(params, Textures(&mask, &mask));
            for (int y = 0; y < kH; ++y)
                for (int bx = 0; bx < kW; bx += 8) {
                    float row[8];
#if SSAM_COMPOSITE_SSE2
                    const bool inside = bx + 8 <= kW;
#else
                    const bool inside = false;  // a build without SSE2 has no row of factors
#endif
                    ASSERT_EQ(kernel.compositeFactorRow(bx, y, row), inside) << bx;
                    for (int i = 0; inside && i < 8; ++i) {
                        const float expected = kernel.compositeFactor(bx + i, y);
                        ASSERT_EQ(std::bit_cast<std::uint32_t>(row[i]), std::bit_cast<std::uint32_t>(expected))
                            << "lerp " << lerp << (square ? " squared" : "") << ", pixel (" << bx + i << ", " << y
                            << "): " << row[i] << " != " << expected;
                    }
                }
        }
    ssam::CompositeParams split;
    split.foliage = {1, 1};
    split.mask = {2, 1};
    split.maskAdd = {2, 1};
    float row[8];
    EXPECT_FALSE(ssam::CompositeKernel(split, Textures(&mask, &mask)).compositeFactorRow(0, 0, row));
}

TEST(CompositeRows, TheTexelItselfWithoutBlurAndNoFastPathWhenFading) {
    Lcg rng{7};
    const soft::SoftTexture foliage = randomFoliage(16, 4, Format::RGBA8_SRGB, rng);
    ssam::CompositeParams params;
    params.foliage = {1, 1};
    params.mask = {2, 1};
    const ssam::CompositeKernel plain(params, Textures(&foliage, &foliage));
    glm::vec3 out[8];
    EXPECT_FALSE(plain.compositeColorRow(0, 0, 0xFFu, out));
    EXPECT_EQ(plain.compositeColor(), &foliage);
    params.colorFade = {0.25f, 0.5f};
    const ssam::CompositeKernel fading(params, Textures(&foliage, &foliage));
    EXPECT_EQ(fading.compositeColor(), nullptr);
}

}  // namespace
