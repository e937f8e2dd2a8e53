// SPDX-License-Identifier: MIT
// SSAM+'s blurred composite on the soft backend (CoverageBlurCompositeKernel, program_kernels.hpp):
// its row hooks (the general path's shadeRow, the 8-bit composite fast path's compositeColorRow)
// against the formula as written before it had one -- each of the nine neighbours fetched on its
// own, the written ones (alpha > 0, NaN not) weighted 1-2-1 by 1-2-1 and by their alpha^1.5
// (clamped to 1), and summed row by row -- bit
// for bit, over random float and sRGB 8-bit foliage with unwritten and NaN texels, image borders
// and partly live rows. The pictures stay the same (Racer.Golden.technique_ssam-plus pins them too).
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

#include <gtest/gtest.h>

#include "lcg.hpp"  // tests/support
#include "program_kernels.hpp"
#include "row_hook_check.hpp"  // tests/support
#include "soft_image.hpp"      // tests/support

namespace {

namespace soft = engine::render::soft;
using engine::render::Format;
using ssam::testing::Lcg;

soft::SoftTexture randomImage(int w, int h, Lcg& rng, bool withNan) {
    soft::SoftTexture t = ssam::testing::softImage(w, h, Format::RGBA32F, 16);
    for (int i = 0; i < w * h; ++i) {
        float texel[4];
        for (float& v : texel) v = rng.unit();
        const float u = rng.unit();
        if (u < 0.3f) texel[3] = 0.0f;                                                 // nothing written
        if (withNan && u > 0.97f) texel[3] = std::numeric_limits<float>::quiet_NaN();  // nor here
        std::memcpy(t.levels[0].texels.data() + 16 * std::size_t(i), texel, sizeof texel);
    }
    return t;
}

// The colour pass's own format: sRGB 8-bit, alpha 0 where nothing was written.
soft::SoftTexture randomSrgbImage(int w, int h, Lcg& rng) {
    soft::SoftTexture t = ssam::testing::softImage(w, h, Format::RGBA8_SRGB, 4);
    for (int i = 0; i < w * h; ++i) {
        std::byte* texel = t.levels[0].texels.data() + 4 * std::size_t(i);
        for (int c = 0; c < 4; ++c) texel[c] = std::byte(std::uint8_t(rng.unit() * 256.0f));
        if (rng.unit() < 0.3f) texel[3] = std::byte{0};
    }
    return t;
}

// The composite's colour as it was computed before the row hook.
glm::vec3 referenceBlur(const soft::SoftTexture& foliage, int px, int py) {
    const int width = foliage.desc.width, height = foliage.desc.height;
    glm::vec3 sum(0.0f);
    float weights = 0.0f;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            const int x = px + dx, y = py + dy;
            if (x < 0 || y < 0 || x >= width || y >= height) continue;
            const glm::vec4 c = soft::fetchTexel(foliage, x, y);
            if (!(c.a > 0.0f)) continue;
            const float alpha = c.a < 1.0f ? c.a : 1.0f;
            const float weight = float((2 - dx * dx) * (2 - dy * dy)) * (alpha * std::sqrt(alpha));
            sum += weight * glm::vec3(c);
            weights += weight;
        }
    glm::vec3 color = weights > 0.0f ? sum / weights : glm::vec3(soft::fetchTexel(foliage, px, py));
    for (int c = 0; c < 3; ++c)
        if (!std::isfinite(color[c])) color[c] = 0.0f;
    return color;
}

TEST(BlurCompositeRows, RowHookAndShadeGiveTheBitsOfTheFormula) {
    Lcg rng{20261206};
    constexpr int kW = 45, kH = 23;  // rows end in partial blocks
    for (int trial = 0; trial < 6; ++trial) {
        const soft::SoftTexture foliage =
            trial >= 4 ? randomSrgbImage(kW, kH, rng) : randomImage(kW, kH, rng, trial % 2 == 1);
        const soft::SoftTexture mask = randomImage(kW, kH, rng, false);
        struct Textures final : soft::TextureLookup {
            const soft::SoftTexture *foliage, *mask;
            Textures(const soft::SoftTexture* f, const soft::SoftTexture* m) : foliage(f), mask(m) {}
            const soft::SoftTexture* texture(engine::render::TextureHandle h) const override {
                return !h ? nullptr : h.index == 1 ? foliage : mask;
            }
        };
        transparency::CoverageCompositeParams params;
        params.foliage = {1, 1};
        params.mask = {2, 1};
        const transparency::CoverageBlurCompositeKernel kernel(params, Textures(&foliage, &mask));
        for (int y = 0; y < kH; ++y)
            for (int bx = 0; bx < kW; bx += 8) {
                const std::uint32_t live = ssam::testing::liveLanes(bx, y, kW, rng);
                glm::vec4 row[8];
                kernel.shadeRow(soft::SimdIsa::Sse2, bx, y, live, row);
                for (int i = 0; i < 8; ++i) {
                    if (!((live >> i) & 1u)) continue;
                    soft::Fragment f;
                    f.x = bx + i, f.y = y;
                    const glm::vec4 shaded = kernel.shade(f);
                    const glm::vec3 expected = referenceBlur(foliage, f.x, y);
                    for (int c = 0; c < 3; ++c) {
                        ASSERT_EQ(std::bit_cast<std::uint32_t>(row[i][c]), std::bit_cast<std::uint32_t>(expected[c]))
                            << "row hook, pixel (" << f.x << ", " << y << ") channel " << c << ", trial " << trial;
                        ASSERT_EQ(std::bit_cast<std::uint32_t>(shaded[c]), std::bit_cast<std::uint32_t>(expected[c]))
                            << "shade, pixel (" << f.x << ", " << y << ") channel " << c;
                    }
                    ASSERT_EQ(std::bit_cast<std::uint32_t>(row[i].a), std::bit_cast<std::uint32_t>(shaded.a));
                }
            }
        ASSERT_TRUE(ssam::testing::compositeColorRowMatchesShade(kernel, kW, kH, rng)) << "trial " << trial;
    }
}

// Random front layers (CoverageCompositeParams::frontLayers), some with no layer in front, some
// with means above 1, some NaN: each kernel's row hooks give shade()'s bits (compositeColorRow
// shade()'s colour clamped to [0, 1], as the 8-bit target's blend clamps it).
TEST(BlurCompositeRows, FrontLayersRowsGiveTheBitsOfShade) {
    Lcg rng{20261207};
    constexpr int kW = 45, kH = 23;
    for (int trial = 0; trial < 4; ++trial) {
        const soft::SoftTexture foliage = trial >= 2 ? randomSrgbImage(kW, kH, rng) : randomImage(kW, kH, rng, true);
        const soft::SoftTexture mask = randomImage(kW, kH, rng, false);
        soft::SoftTexture front = randomImage(kW, kH, rng, true);
        for (std::size_t i = 0; i < std::size_t(kW * kH); ++i) {  // sums of a few layers: up to 3 times a colour
            float texel[4];
            std::memcpy(texel, front.levels[0].texels.data() + 16 * i, sizeof texel);
            for (int c = 0; c < 3; ++c) texel[c] *= 3.0f;
            std::memcpy(front.levels[0].texels.data() + 16 * i, texel, sizeof texel);
        }
        struct Textures final : soft::TextureLookup {
            const soft::SoftTexture* t[3];
            const soft::SoftTexture* texture(engine::render::TextureHandle h) const override {
                return !h ? nullptr : t[h.index - 1];
            }
        } textures;
        textures.t[0] = &foliage, textures.t[1] = &mask, textures.t[2] = &front;
        transparency::CoverageCompositeParams params;
        params.foliage = {1, 1};
        params.mask = {2, 1};
        params.frontLayers = {3, 1};
        const transparency::CoverageBlurCompositeKernel blurred(params, textures);
        const transparency::CoverageCompositeKernel plain(params, textures);
        ASSERT_TRUE(ssam::testing::rowHookMatchesShade(blurred, soft::SimdIsa::Sse2, kW, kH, rng, [](auto&) {}))
            << "trial " << trial;
        // compositeColorRow against shade()'s colour clamped as the blend clamps it.
        auto clampedShade = [&](const auto& kernel) {
            struct Clamped {
                decltype(kernel)& k;
                glm::vec4 shade(const soft::Fragment& f) const { return glm::clamp(k.shade(f), 0.0f, 1.0f); }
                bool compositeColorRow(int bx, int y, std::uint32_t live, glm::vec3* out) const {
                    return k.compositeColorRow(bx, y, live, out);
                }
            };
            return Clamped{kernel};
        };
        ASSERT_TRUE(ssam::testing::compositeColorRowMatchesShade(clampedShade(blurred), kW, kH, rng)) << trial;
        ASSERT_TRUE(ssam::testing::compositeColorRowMatchesShade(clampedShade(plain), kW, kH, rng)) << trial;
    }
}

}  // namespace
