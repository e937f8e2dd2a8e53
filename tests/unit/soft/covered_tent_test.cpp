// SPDX-License-Identifier: MIT
// The covered-texel tent window (engine/render/kernel/covered_tent.hpp) that SSAM's and SSAM+'s
// blurred composites share: what load() holds is each texel as loadTexel decodes it, its
// coverage and its alpha weight, whether a row is read four texels at a time (RGBA8 inside the
// texture) or texel by texel (borders, other formats); and filteredRow, four pixels at a time,
// gives filtered()'s bits in every lane, over partial coverage, NaN, infinities and signed zeros.
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

#include <gtest/gtest.h>

#include "engine/render/kernel/covered_tent.hpp"
#include "lcg.hpp"         // tests/support
#include "soft_image.hpp"  // tests/support

namespace {

namespace soft = engine::render::soft;
using engine::render::Format;
using ssam::testing::Lcg;
using Window = soft::CoveredTentWindow<8>;

bool sameBits(float a, float b) { return std::bit_cast<std::uint32_t>(a) == std::bit_cast<std::uint32_t>(b); }

// Random RGBA8 texels: a third unwritten (alpha 0), some fully covered (255), the rest any byte.
soft::SoftTexture randomBytes(int w, int h, Format format, Lcg& rng) {
    soft::SoftTexture t = ssam::testing::softImage(w, h, format, 4);
    for (std::byte& b : t.levels[0].texels) b = std::byte(std::uint8_t(rng.next()));
    for (int i = 0; i < w * h; ++i) {
        const float pick = rng.unit();
        if (pick < 0.3f) t.levels[0].texels[4 * std::size_t(i) + 3] = std::byte{0};
        else if (pick < 0.4f) t.levels[0].texels[4 * std::size_t(i) + 3] = std::byte{255};
    }
    return t;
}

// Random RGBA32F texels with the values a float colour pass can leave: partial, zero and
// negative-zero alphas, alphas above 1, NaN and infinities in any channel.
soft::SoftTexture randomFloats(int w, int h, Lcg& rng) {
    soft::SoftTexture t = ssam::testing::softImage(w, h, Format::RGBA32F, 16);
    const float specials[] = {0.0f,
                              -0.0f,
                              1.0f,
                              2.5f,
                              -1.0f,
                              std::numeric_limits<float>::infinity(),
                              -std::numeric_limits<float>::infinity(),
                              std::numeric_limits<float>::quiet_NaN(),
                              1.0e-30f};
    for (int i = 0; i < w * h * 4; ++i) {
        const float v = rng.unit() < 0.15f ? specials[rng.next() % std::size(specials)] : rng.unit();
        std::memcpy(t.levels[0].texels.data() + 4 * std::size_t(i), &v, sizeof v);
    }
    return t;
}

// What load() must hold at row `row`, column `column` of the window from (x0, y).
::testing::AssertionResult holdsTexel(const Window& w, const soft::SoftTexture& t, int x0, int y, int row, int column) {
    const int x = x0 + column - 1, yy = y + row - 1;
    const bool inside = x >= 0 && yy >= 0 && x < t.desc.width && yy < t.desc.height;
    const glm::vec4 texel = inside ? engine::render::loadTexel(t.texel(0, x, yy), t.desc.format) : glm::vec4(0.0f);
    const bool covered = texel.a > 0.0f;
    const float alpha = texel.a < 1.0f ? texel.a : 1.0f;
    const float weight = covered ? alpha * std::sqrt(alpha) : 0.0f;
    for (int c = 0; c < 4; ++c)
        if (!sameBits(w.channel[c][row][column], texel[c]))
            return ::testing::AssertionFailure() << "texel (" << x << ", " << yy << ") channel " << c << ": "
                                                 << w.channel[c][row][column] << " != " << texel[c];
    if (!sameBits(w.alphaWeight[row][column], weight) || (w.coveredBits[row][column] != 0) != covered)
        return ::testing::AssertionFailure()
               << "texel (" << x << ", " << yy << "): weight " << w.alphaWeight[row][column] << " != " << weight;
    return ::testing::AssertionSuccess();
}

// Every window position of the texture (borders included): load() as holdsTexel says, and
// filteredRow's lanes filtered()'s bits.
void checkEveryWindow(const soft::SoftTexture& t, Lcg& rng) {
    for (int y = -1; y <= t.desc.height; ++y)
        for (int x0 = -2; x0 < t.desc.width; x0 += 3) {
            Window w;
            w.load(t, x0, y, 8);
            for (int row = 0; row < 3; ++row)
                for (int column = 0; column < Window::kColumns; ++column)
                    ASSERT_TRUE(holdsTexel(w, t, x0, y, row, column)) << "window at (" << x0 << ", " << y << ")";
            const std::uint32_t live = rng.unit() < 0.25f ? std::uint32_t(rng.next() & 0xFFu) : 0xFFu;
            glm::vec3 rows[8];
            w.filteredRow(live, rows);
            for (int i = 0; i < 8; ++i) {
                if (!((live >> i) & 1u)) continue;
                const glm::vec3 expected = w.filtered(i);
                for (int c = 0; c < 3; ++c)
                    ASSERT_TRUE(sameBits(rows[i][c], expected[c]))
                        << "window at (" << x0 << ", " << y << "), pixel " << i << ", channel " << c << ": "
                        << rows[i][c] << " != " << expected[c];
            }
        }
}

TEST(CoveredTent, Rgba8WindowsHoldTheDecodedTexelsAndRowsFilterAsPixelsDo) {
    Lcg rng{20261207};
    for (Format format : {Format::RGBA8_SRGB, Format::RGBA8_UNORM}) {
        SCOPED_TRACE(engine::render::formatName(format));
        checkEveryWindow(randomBytes(29, 7, format, rng), rng);
    }
}

TEST(CoveredTent, FloatWindowsWithNonFiniteAndSignedZeroTexelsFilterAsPixelsDo) {
    Lcg rng{7};
    checkEveryWindow(randomFloats(29, 7, rng), rng);
}

TEST(CoveredTent, AnUncoveredWindowGivesTheCentreTexel) {
    Lcg rng{3};
    soft::SoftTexture t = randomBytes(16, 3, Format::RGBA8_SRGB, rng);
    for (int i = 0; i < 16 * 3; ++i) t.levels[0].texels[4 * std::size_t(i) + 3] = std::byte{0};
    Window w;
    w.load(t, 4, 1, 8);
    for (int i = 0; i < 8; ++i) {
        const glm::vec4 centre = w.texel(1, i + 1);
        EXPECT_EQ(w.filtered(i), glm::vec3(centre)) << i;
    }
}

}  // namespace
