// SPDX-License-Identifier: MIT
// Sharpened alpha to coverage [Golus 2017] (transparency/sharpened_coverage.hpp) on the soft
// backend: the formula, the program's derivative from its quad partner, and the a2c-sharp
// techniques' coverage.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "sharpened_coverage_frame.hpp"
#include "engine/core/error.hpp"
#include "engine/render/soft/soft_backend.hpp"
#include "transparency/create_technique.hpp"

namespace {

using namespace transparency;
using namespace transparency::testing;

std::unique_ptr<engine::render::Device> softBackend() { return engine::render::soft::createSoftBackend({}); }

TEST(SharpenedCoverage, RescalesAlphaAroundTheReferenceByItsWidth) {
    EXPECT_EQ(sharpenedCoverage(0.5f, 0.1f, 0.5f), 0.5f);          // at the reference: half covered
    EXPECT_FLOAT_EQ(sharpenedCoverage(0.55f, 0.2f, 0.5f), 0.75f);  // a quarter of the width above
    EXPECT_EQ(sharpenedCoverage(0.7f, 0.1f, 0.5f), 1.0f);          // two widths above: clamped
    EXPECT_EQ(sharpenedCoverage(0.3f, 0.1f, 0.5f), 0.0f);
    // Flat alpha (no derivative) is the alpha test: all or nothing.
    EXPECT_EQ(sharpenedCoverage(0.5001f, 0.0f, 0.5f), 1.0f);
    EXPECT_EQ(sharpenedCoverage(0.4999f, 0.0f, 0.5f), 0.0f);
    // An infinite width (a NaN-free degenerate derivative) leaves half coverage, not NaN.
    EXPECT_EQ(sharpenedCoverage(0.9f, std::numeric_limits<float>::infinity(), 0.5f), 0.5f);
}

// The ramp crosses 0.45 between columns 28 and 29: column 29 is the one partly covered pixel
// of each row, every column left of it none and right of it all, as the formula says.
TEST(SharpenedCoverage, ProgramMakesTheAlphaRampsEdgeOnePixelWide) {
    auto backend = softBackend();
    const engine::render::Readback r = drawSharpenedRamp(*backend, 0.45f);
    EXPECT_EQ(expectSharpenedRamp(r, 0.45f, 2e-3f), 1);
    EXPECT_NEAR(r.at(29, 7, 3), 0.76f, 0.02f);
    // The alpha test's shape: sharpened alpha reaches 0.5 where alpha reaches the reference.
    for (int x = 0; x < kRampPixels; ++x) EXPECT_EQ(r.at(x, 0, 3) >= 0.5f, rampAlpha(x) >= 0.45f) << x;
}

TEST(SharpenedCoverage, ProgramRefusesAReferenceOutsideZeroToOne) {
    auto backend = softBackend();
    EXPECT_THROW(drawSharpenedRamp(*backend, 1.5f), engine::Error);
    EXPECT_THROW(drawSharpenedRamp(*backend, std::nanf("")), engine::Error);
}

TEST(SharpenedCoverage, TechniqueRefusesAReferenceOutsideZeroToOne) {
    auto backend = softBackend();
    TechniqueOptions options;
    options.alphaTestReference = -0.25f;
    EXPECT_THROW(createTechnique(TechniqueKind::AlphaToCoverageSharp, *backend, options), engine::Error);
}

}  // namespace
