// SPDX-License-Identifier: MIT
// The dithered level-of-detail crossfade (transparency/lod_dither.hpp): two neighbouring levels
// keep complementary pixels, and the program keeps what the function says with the weight
// divided out of its alpha.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "lod_dither_card.hpp"
#include "technique_fixture.hpp"
#include "engine/core/error.hpp"
#include "engine/render/soft/soft_backend.hpp"

namespace {

using namespace transparency;
using namespace transparency::testing;

constexpr std::array<float, 7> kWeights{0.0f, 0.1f, 0.3f, 0.5f, 0.7f, 0.9f, 1.0f};

TEST(LodDither, ThresholdsAreTheSixteenLevelsOnceInEveryFourByFourBlock) {
    for (int oy : {0, 4, 9}) {
        std::array<int, 16> seen{};
        for (int y = oy; y < oy + 4; ++y)
            for (int x = 4; x < 8; ++x) ++seen[std::size_t(lodDitherThreshold(x, y) * 16.0f - 0.5f)];
        for (int k = 0; k < 16; ++k) EXPECT_EQ(seen[std::size_t(k)], 1) << k;
    }
}

// A crossfade pairs level k (weight 1 - w) with k + 1 (weight w), k even or odd: every pixel
// is kept by exactly one of them, and the coarser one keeps w of them (to 1/16).
TEST(LodDither, NeighbouringLevelsKeepComplementaryPixels) {
    for (const bool finerEven : {true, false}) {
        const LodDither finer = lodDitherFor(finerEven ? 0 : 1, true), coarser = lodDitherFor(finerEven ? 1 : 2, true);
        ASSERT_NE(finer, coarser);
        for (const float w : kWeights) {
            int coarserPixels = 0;
            for (int y = 0; y < 4; ++y)
                for (int x = 0; x < 4; ++x) {
                    const bool a = lodDitherKeeps(finer, 1.0f - w, x, y), b = lodDitherKeeps(coarser, w, x, y);
                    EXPECT_NE(a, b) << "w " << w << " at " << x << "," << y;
                    coarserPixels += b;
                }
            EXPECT_LE(std::abs(float(coarserPixels) / 16.0f - w), 1.0f / 16.0f) << w;
        }
    }
    EXPECT_EQ(lodDitherFor(2, false), LodDither::Off);
    EXPECT_TRUE(lodDitherKeeps(LodDither::Off, 0.0f, 3, 1));  // steady batches are not dithered
}

TEST(LodDither, ProgramKeepsTheLevelsPixelsWithTheWeightDividedOut) {
    auto backend = engine::render::soft::createSoftBackend({});
    for (const LodDither dither : {LodDither::KeepBelow, LodDither::KeepAbove})
        for (const float w : {0.3f, 0.7f}) {
            const engine::render::Readback r = drawDitheredCard(*backend, w, dither);
            for (int y = 0; y < kDitherCardPixels; ++y)
                for (int x = 0; x < kDitherCardPixels; ++x)
                    EXPECT_EQ(r.at(x, y, 3), lodDitherKeeps(dither, w, x, y) ? 1.0f : 0.0f)
                        << int(dither) << " w " << w << " at " << x << "," << y;
        }
    // Off is MaskedLit: the weight stays in alpha.
    EXPECT_FLOAT_EQ(drawDitheredCard(*backend, 0.3f, LodDither::Off).at(5, 5, 3), 0.3f);
}

TEST(LodDither, ProgramRefusesAValueOutsideTheEnum) {
    auto backend = engine::render::soft::createSoftBackend({});
    EXPECT_THROW(drawDitheredCard(*backend, 0.5f, LodDither(7)), engine::Error);
}

// A plant inside a crossfade band under each technique that cannot fade by alpha: its finer
// level (red, weight 0.4) and its coarser one (green, 0.6) over the same square. Faded by
// alpha, the alpha test at 0.5 would drop the finer level whole; dithered, every pixel is one
// level's colour, the coarser level's in about 0.6 of them.
TEST(LodDither, CrossfadingLevelsShareThePixelsUnderEveryTechniqueThatTests) {
    for (const TechniqueKind kind : {TechniqueKind::AlphaTest, TechniqueKind::AlphaToCoverage, TechniqueKind::Hashed,
                                     TechniqueKind::AlphaToCoverageSharp, TechniqueKind::AlphaToCoverage8}) {
        auto backend = engine::render::soft::createSoftBackend({});
        auto technique = createTechnique(kind, *backend, {});
        const Quad finer{-1.0f, -1.0f, 1.0f, 1.0f, 0.5f, {1.0f, 0.0f, 0.0f, 0.4f}};
        const Quad coarser{-1.0f, -1.0f, 1.0f, 1.0f, 0.5f, {0.0f, 1.0f, 0.0f, 0.6f}};
        TechniqueFrame f(*backend, technique->opaqueSamples(), {finer, coarser});
        f.draws[0].lodLevel = 1, f.draws[1].lodLevel = 2;  // an odd-even pair
        for (FoliageDraw& d : f.draws) d.crossfading = true;
        const Readback r = f.run(*technique);
        int green = 0;
        for (int y = 0; y < kSize; ++y)
            for (int x = 0; x < kSize; ++x) {
                const glm::vec3 c = rgbAt(r, x, y);
                const bool red = c == glm::vec3(1, 0, 0), isGreen = c == glm::vec3(0, 1, 0);
                EXPECT_TRUE(red || isGreen)
                    << techniqueName(kind) << " at " << x << "," << y << ": " << c.r << " " << c.g << " " << c.b;
                green += isGreen;
            }
        EXPECT_NEAR(float(green) / float(kSize * kSize), 0.6f, 1.0f / 16.0f) << techniqueName(kind);
    }
}

}  // namespace
