// SPDX-License-Identifier: MIT
#pragma once
// SSAM's exact synthetic cases ([Hathaway 2010] §3.5-3.7), written once and run on every render
// backend: each backend's test binary instantiates them with its BackendKind
//   struct BackendKind {
//       static std::unique_ptr<engine::render::Backend> create();
//       static constexpr float kBlendTolerance;  // composite results, in [0,1] units
//   };
// (ssam_test.cpp: soft, 1/255 for the rounding of the expected value itself; ssam_gl_backend_test.cpp:
// GL, 2/255 because llvmpipe blends RGBA8 in 8-bit fixed point, README "Differential tolerances").
// Everything else (masks, depths, alpha-tested colour) is exact on both.
#include <gtest/gtest.h>

#include <cmath>
#include <algorithm>
#include <memory>
#include <utility>
#include <string>
#include <vector>

#include "engine/core/error.hpp"
#include "engine/render/backend.hpp"
#include "engine/render/frame_graph/transient_texture_pool.hpp"
#include "engine/render/frame_targets.hpp"
#include "quad_scene.hpp"
#include "run_ssam.hpp"
#include "ssam/frame_graph_passes.hpp"
#include "ssam/ssam.hpp"

namespace ssam_cases {

using namespace engine::render;
using ssam::testing::Quad;
using ssam::testing::QuadBatches;

// How many SSAM passes the backend ran since its timings were last taken (every pass is timed
// on both backends; GL waits for its queries).
inline int ssamPassesTimed(Backend& backend) {
    int n = 0;
    for (const PassTiming& t : backend.takeTimings()) n += t.pass.rfind("ssam", 0) == 0 ? 1 : 0;
    return n;
}

template <typename BackendKind>
class SsamCases : public ::testing::Test {};
TYPED_TEST_SUITE_P(SsamCases);

constexpr int kSize = 16;
inline const glm::vec4 kOpaqueColor{0.2f, 0.4f, 0.6f, 1.0f};

// Unlit foliage: ambient 1, no direct light, so the foliage colour is the vertex colour.
inline DirectionalLight unlit() { return {{0.0f, 0.0f, 1.0f}, glm::vec3(0.0f), glm::vec3(1.0f)}; }

inline float q8(float v) { return std::round(std::clamp(v, 0.0f, 1.0f) * 255.0f) / 255.0f; }

template <typename BackendKind>
struct Frame {
    std::unique_ptr<Backend> backend = BackendKind::create();
    engine::render::FrameTargets opaque;
    explicit Frame(int samples = 1)
        : opaque(*backend, {kSize, kSize, samples, Format::RGBA8_UNORM, CompareFunc::Less}) {}

    // The opaque pass: clear to kOpaqueColor and far depth, optionally draw an opaque quad.
    void opaquePass(const std::vector<Quad>& quads = {}) {
        PipelineDesc p;
        p.name = "opaque flat";
        p.depth = DepthState::testAndWrite();
        const PipelineHandle pipeline = backend->createPipeline(p);
        QuadBatches geometry(*backend, quads);
        backend->beginPass(opaque.passDesc(kOpaqueColor));
        geometry.drawFlat(pipeline);
        backend->endPass();
        opaque.resolve();
        backend->destroy(pipeline);
    }
    ssam::FrameTargets targets() const { return {opaque.color(), opaque.depth()}; }
};

inline ssam::FoliageView viewOf(const QuadBatches& q) { return {glm::mat4(1.0f), unlit(), q.batches}; }

// Left quad A (alpha 0.4, nearer) and right quad B (alpha 0.2, farther) overlap in the middle.
inline const Quad kQuadA{-1.0f, -1.0f, 0.25f, 1.0f, 0.3f, {1.0f, 0.0f, 0.0f, 0.4f}};
inline const Quad kQuadB{-0.25f, -1.0f, 1.0f, 1.0f, 0.6f, {0.0f, 1.0f, 0.0f, 0.2f}};
constexpr int kOnlyA = 1, kOverlap = 8, kOnlyB = 14;  // pixel columns

TYPED_TEST_P(SsamCases, CrossingQuadsGiveMaxAndAddMasks) {
    Frame<TypeParam> f;
    f.opaquePass();
    ssam::ScreenSpaceAlphaMask ssam(*f.backend);
    QuadBatches q(*f.backend, {kQuadA, kQuadB});
    const Readback mask = test_support::runSsam(ssam, f.targets(), viewOf(q), true).mask;
    // RGB = MAX (§3.5.2 "alpha-z-buffer"), A = ADD.
    EXPECT_FLOAT_EQ(mask.at(kOnlyA, 4, 0), q8(0.4f));
    EXPECT_FLOAT_EQ(mask.at(kOnlyA, 4, 3), q8(0.4f));
    EXPECT_FLOAT_EQ(mask.at(kOverlap, 4, 0), q8(0.4f));
    EXPECT_FLOAT_EQ(mask.at(kOverlap, 4, 1), q8(0.4f));  // alpha replicated to every channel
    EXPECT_FLOAT_EQ(mask.at(kOverlap, 4, 3), q8(0.6f));
    EXPECT_FLOAT_EQ(mask.at(kOnlyB, 4, 0), q8(0.2f));
    EXPECT_FLOAT_EQ(mask.at(kOnlyB, 4, 3), q8(0.2f));
}

TYPED_TEST_P(SsamCases, ColourPassAlphaTestsAndWritesFoliageDepth) {
    Frame<TypeParam> f;
    f.opaquePass();
    ssam::ScreenSpaceAlphaMask ssam(*f.backend);  // colour reference 64/255: A (0.4) passes, B (0.2) fails
    QuadBatches q(*f.backend, {kQuadA, kQuadB});
    const Readback foliage = test_support::runSsam(ssam, f.targets(), viewOf(q), true).foliage;
    const Readback depth = f.backend->readback(f.opaque.depth());
    const float clearGreen = ssam::Settings{}.foliageClearColor[1];
    EXPECT_FLOAT_EQ(foliage.at(kOverlap, 4, 0), 1.0f);          // A's red
    EXPECT_FLOAT_EQ(foliage.at(kOnlyB, 4, 1), q8(clearGreen));  // B rejected: the clear colour shows
    EXPECT_NEAR(depth.at(kOverlap, 4, 0), 0.3f, 1e-6f);
    EXPECT_NEAR(depth.at(kOnlyB, 4, 0), 1.0f, 1e-6f);  // nothing written where B was rejected
}

TYPED_TEST_P(SsamCases, CompositeFollowsListing32) {
    for (const bool square : {true, false}) {
        for (const float lerp : {0.0f, 0.85f, 1.0f}) {
            Frame<TypeParam> f;
            f.opaquePass();
            ssam::Settings config;
            config.squareMask = square;
            config.maskLerp = lerp;
            ssam::ScreenSpaceAlphaMask ssam(*f.backend, config);
            QuadBatches q(*f.backend, {kQuadA, kQuadB});
            test_support::runSsam(ssam, f.targets(), viewOf(q));
            const Readback result = f.backend->readback(f.opaque.color());
            // mask = lerp(max, add, maskLerp) from the stored 8-bit masks; result = lerp(opaque, foliage, m^2).
            float m = q8(0.4f) + (q8(0.6f) - q8(0.4f)) * lerp;
            if (square) m *= m;
            const float expectedRed = kOpaqueColor.r + (1.0f - kOpaqueColor.r) * m;
            const float expectedGreen = kOpaqueColor.g + (0.0f - kOpaqueColor.g) * m;
            SCOPED_TRACE(::testing::Message() << "square=" << square << " lerp=" << lerp);
            EXPECT_NEAR(result.at(kOverlap, 4, 0), q8(expectedRed), TypeParam::kBlendTolerance);
            EXPECT_NEAR(result.at(kOverlap, 4, 1), q8(expectedGreen), TypeParam::kBlendTolerance);
            EXPECT_FLOAT_EQ(result.at(kOverlap, 4, 3), 1.0f);  // the opaque alpha is kept
        }
    }
}

TYPED_TEST_P(SsamCases, SquaringAndLerpChangeTheResultAsTheFormulaSays) {
    auto overlapRed = [](ssam::Settings config) {
        Frame<TypeParam> f;
        f.opaquePass();
        ssam::ScreenSpaceAlphaMask ssam(*f.backend, config);
        QuadBatches q(*f.backend, {kQuadA, kQuadB});
        test_support::runSsam(ssam, f.targets(), viewOf(q));
        return f.backend->readback(f.opaque.color()).at(kOverlap, 4, 0);
    };
    ssam::Settings squared, linear, maxOnly;
    linear.squareMask = false;
    maxOnly.maskLerp = 0.0f;
    // m in (0,1): squaring lowers the foliage weight; more ADD (0.6 > 0.4) raises it.
    EXPECT_LT(overlapRed(squared), overlapRed(linear));
    EXPECT_LT(overlapRed(maxOnly), overlapRed(squared));
}

// The composited red at (kOverlap, 4) of `quads` under SSAM with `config`, on the opaque clear colour.
template <typename BackendKind>
float compositedRed(const ssam::Settings& config, const std::vector<Quad>& quads) {
    Frame<BackendKind> f;
    f.opaquePass();
    ssam::ScreenSpaceAlphaMask ssam(*f.backend, config);
    QuadBatches q(*f.backend, quads);
    test_support::runSsam(ssam, f.targets(), viewOf(q));
    return f.backend->readback(f.opaque.color()).at(kOverlap, 4, 0);
}

// Settings::colorFade: a leaf whose alpha crosses the colour reference (64/255) between two frames
// changes the pixel by about alpha * |leaf - clear colour| without the fade (the colour pass's
// step, §3.5.3), by no more than its mask's change with it; past reference + fade the picture is
// the step's.
TYPED_TEST_P(SsamCases, ColourFadeKeepsALeafCrossingTheReferenceFromJumping) {
    auto red = [](float alpha, float fade) {
        ssam::Settings config;
        config.squareMask = false;
        config.colorFade = fade;
        return compositedRed<TypeParam>(config, {{-1.0f, -1.0f, 1.0f, 1.0f, 0.3f, {1.0f, 0.0f, 0.0f, alpha}}});
    };
    const float below = 60.0f / 255.0f, above = 68.0f / 255.0f;
    const float step = std::abs(red(above, 0.0f) - red(below, 0.0f));
    const float faded = std::abs(red(above, 0.5f) - red(below, 0.5f));
    EXPECT_GT(step, 0.15f);  // 0.267 * 1 - 0.235 * 0.16 with the opaque's 0.2 mixed out
    EXPECT_LT(faded, 0.02f);
    EXPECT_NEAR(red(0.9f, 0.5f), red(0.9f, 0.0f), TypeParam::kBlendTolerance);
    EXPECT_NEAR(red(below, 0.5f), red(below, 0.0f), TypeParam::kBlendTolerance);  // the clear colour either way
}

// Settings::colorBlur: a one-pixel red leaf over a green one moves a pixel between two frames; the
// pixel it leaves changes from red to green at once with the pixel's own colour, by about a
// quarter of that with the 3x3 average (its red share goes from 8/16 to 4/16).
TYPED_TEST_P(SsamCases, ColourBlurSoftensALeafMovingAPixel) {
    auto red = [](float x0, bool blur) {
        ssam::Settings config;
        config.colorBlur = blur;
        return compositedRed<TypeParam>(config, {{x0, -1.0f, x0 + 2.0f / kSize, 1.0f, 0.3f, {1.0f, 0.0f, 0.0f, 0.9f}},
                                                 {-1.0f, -1.0f, 1.0f, 1.0f, 0.6f, {0.0f, 1.0f, 0.0f, 0.9f}}});
    };
    const float step = std::abs(red(0.0f, false) - red(2.0f / kSize, false));
    const float blurred = std::abs(red(0.0f, true) - red(2.0f / kSize, true));
    EXPECT_GT(step, 0.8f);
    EXPECT_LT(blurred, 0.4f * step);
    EXPECT_GT(blurred, 0.1f);  // the average, not a blank: the leaf still shows
}

TYPED_TEST_P(SsamCases, Rgba8AddMaskSaturatesWhereFloatMasksDoNot) {
    constexpr int kLayers = 12;  // 12 layers of alpha 0.1: ADD = 1.2
    std::vector<Quad> quads;
    for (int i = 0; i < kLayers; ++i) quads.push_back({-1, -1, 1, 1, 0.1f + 0.05f * i, {0.5f, 0.5f, 0.5f, 0.1f}});
    for (const auto precision :
         {ssam::MaskPrecision::Rgba8, ssam::MaskPrecision::Rgba16f, ssam::MaskPrecision::Rg16f}) {
        Frame<TypeParam> f;
        f.opaquePass();
        ssam::Settings config;
        config.maskPrecision = precision;
        ssam::ScreenSpaceAlphaMask ssam(*f.backend, config);
        QuadBatches q(*f.backend, quads);
        const test_support::SsamRun run = test_support::runSsam(ssam, f.targets(), viewOf(q), true);
        const Readback& mask = run.mask;
        const float add = run.maskAdd.values.empty() ? mask.at(3, 3, 3) : run.maskAdd.at(3, 3, 0);
        SCOPED_TRACE(ssam::maskPrecisionName(precision));
        EXPECT_NEAR(mask.at(3, 3, 0), 0.1f, 1.0f / 255.0f);                       // MAX
        if (precision == ssam::MaskPrecision::Rgba8) EXPECT_FLOAT_EQ(add, 1.0f);  // 255/alpha layers saturate (§3.5.2)
        else EXPECT_NEAR(add, 1.2f, 4e-3f);                                       // half precision accumulates past 1
    }
}

TYPED_TEST_P(SsamCases, OpaqueGeometryOccludesFoliageInEveryPass) {
    Frame<TypeParam> f;
    // An opaque quad nearer than both foliage quads over the left half.
    f.opaquePass({{-1.0f, -1.0f, 0.0f, 1.0f, 0.1f, {0.0f, 0.0f, 1.0f, 1.0f}}});
    ssam::ScreenSpaceAlphaMask ssam(*f.backend);
    QuadBatches q(*f.backend, {kQuadA, kQuadB});
    const Readback mask = test_support::runSsam(ssam, f.targets(), viewOf(q), true).mask;
    EXPECT_FLOAT_EQ(mask.at(kOnlyA, 4, 3), 0.0f);
    EXPECT_FLOAT_EQ(f.backend->readback(f.opaque.color()).at(kOnlyA, 4, 2), 1.0f);  // untouched blue
}

TYPED_TEST_P(SsamCases, FoliageDepthOccludesLaterDrawsBehindNotInFront) {
    Frame<TypeParam> f;
    f.opaquePass();
    ssam::ScreenSpaceAlphaMask ssam(*f.backend);
    const Quad solidLeaf{-1.0f, -1.0f, 1.0f, 1.0f, 0.5f, {0.0f, 1.0f, 0.0f, 1.0f}};
    QuadBatches q(*f.backend, {solidLeaf});
    test_support::runSsam(ssam, f.targets(), viewOf(q));
    // A later transparent pass (§3.7): a white quad behind the foliage on the left, in front on the right.
    PipelineDesc p;
    p.name = "later";
    p.depth = DepthState::testOnly();
    const PipelineHandle pipeline = f.backend->createPipeline(p);
    QuadBatches later(*f.backend, {{-1.0f, -1.0f, 0.0f, 1.0f, 0.7f, glm::vec4(1.0f)},
                                   {0.0f, -1.0f, 1.0f, 1.0f, 0.3f, glm::vec4(1.0f)}});
    PassDesc pass;
    pass.name = "later";
    pass.color[0] = {f.opaque.color(), LoadOp::Load};
    pass.depth = {f.opaque.depth(), LoadOp::Load};
    f.backend->beginPass(pass);
    later.drawFlat(pipeline);
    f.backend->endPass();
    const Readback result = f.backend->readback(f.opaque.color());
    EXPECT_FLOAT_EQ(result.at(3, 8, 0), 0.0f);   // behind: hidden by the foliage
    EXPECT_FLOAT_EQ(result.at(12, 8, 0), 1.0f);  // in front: drawn
}

TYPED_TEST_P(SsamCases, NoFoliageInViewRunsNoPass) {
    Frame<TypeParam> f;
    f.opaquePass();
    const Readback before = f.backend->readback(f.opaque.color());
    ssam::ScreenSpaceAlphaMask ssam(*f.backend);
    // A quad entirely behind the camera (z < 0) and one off to the side.
    QuadBatches q(*f.backend, {{-1, -1, 1, 1, -0.5f, glm::vec4(1.0f)}, {3, 3, 4, 4, 0.5f, glm::vec4(1.0f)}});
    (void)f.backend->takeTimings();
    TransientTexturePool pool(*f.backend);
    const ssam::FrameReport report = test_support::runSsam(ssam, f.targets(), viewOf(q), false, &pool).report;
    EXPECT_EQ(report.passesRun, 0);
    EXPECT_EQ(report.batchesVisible, 0);
    EXPECT_EQ(ssamPassesTimed(*f.backend), 0);
    EXPECT_EQ(pool.texturesHeld(), 0u);  // no target was even allocated
    EXPECT_EQ(f.backend->readback(f.opaque.color()).values, before.values);
    // Control: the same SSAM with a visible quad runs and times its three passes.
    QuadBatches visible(*f.backend, {kQuadA});
    EXPECT_EQ(test_support::runSsam(ssam, f.targets(), viewOf(visible), false, &pool).report.passesRun, 3);
    EXPECT_GT(pool.texturesHeld(), 0u);
    (void)f.backend->readback(f.opaque.color());
    EXPECT_EQ(ssamPassesTimed(*f.backend), 3);
}

TYPED_TEST_P(SsamCases, ClosestSampleDepthResolveWithMsaaOpaquePass) {
    Frame<TypeParam> f(4);
    // An opaque quad whose edge cuts pixel column 8 (NDC 0 is its left edge): samples of
    // that column see both the quad (depth 0.2) and the far plane (1.0).
    f.opaquePass({{0.0f - 1.0f / kSize, -1.0f, 1.0f, 1.0f, 0.2f, glm::vec4(1.0f)}});
    const Readback depth = f.backend->readback(f.opaque.depth());
    EXPECT_FLOAT_EQ(depth.at(7, 8, 0), 0.2f);  // mixed pixel: the closest sample, never an average
    EXPECT_FLOAT_EQ(depth.at(2, 8, 0), 1.0f);
    const Readback color = f.backend->readback(f.opaque.color());
    EXPECT_GT(color.at(7, 8, 1), kOpaqueColor.g);  // colour averaged: between the two
    EXPECT_LT(color.at(7, 8, 1), 1.0f);
}

TYPED_TEST_P(SsamCases, MaskProgramIgnoresColour) {
    // NaN colour channels must not reach the mask: it does alpha work only (§3.5.2).
    Frame<TypeParam> f;
    f.opaquePass();
    ssam::ScreenSpaceAlphaMask ssam(*f.backend);
    QuadBatches q(*f.backend, {{-1, -1, 1, 1, 0.5f, {NAN, NAN, NAN, 0.4f}}});
    const Readback mask = test_support::runSsam(ssam, f.targets(), viewOf(q), true).mask;
    EXPECT_FLOAT_EQ(mask.at(5, 5, 0), q8(0.4f));
    EXPECT_FLOAT_EQ(mask.at(5, 5, 3), q8(0.4f));
}

TYPED_TEST_P(SsamCases, BadConfigurationIsRejectedWithTheKnobName) {
    auto backend = TypeParam::create();
    auto expectError = [&](ssam::Settings c, const std::string& knob) {
        try {
            ssam::ScreenSpaceAlphaMask ssam(*backend, c);
            ADD_FAILURE() << "accepted bad " << knob;
        } catch (const engine::Error& e) {
            EXPECT_NE(std::string(e.what()).find(knob), std::string::npos) << e.what();
        }
    };
    ssam::Settings c;
    c.maskLerp = 1.5f;
    expectError(c, "maskLerp");
    c = {};
    c.maskLerp = NAN;
    expectError(c, "maskLerp");
    c = {};
    c.colorAlphaReference = -0.1f;
    expectError(c, "colorAlphaReference");
    c = {};
    c.foliageClearColor[0] = INFINITY;
    expectError(c, "foliageClearColor");
    c = {};
    c.depthMaskThreshold = 2.0f;
    expectError(c, "depthMaskThreshold");
    c = {};
    c.colorFade = -0.5f;
    expectError(c, "colorFade");
    c = {};
    c.depthTest = static_cast<ssam::DepthTest>(9);
    expectError(c, "depthTest");
}

// ---- SSAM as a frame-graph pass group -----------------------------------------------

TYPED_TEST_P(SsamCases, FrameGraphRunsThreePassesWithFoliageAndNoneWithout) {
    Frame<TypeParam> f;
    f.opaquePass();
    ssam::ScreenSpaceAlphaMask ssam(*f.backend);
    QuadBatches visible(*f.backend, {kQuadA, kQuadB});
    EXPECT_EQ(test_support::runSsam(ssam, f.targets(), viewOf(visible)).passes,
              (std::vector<std::string>{"ssam mask", "ssam colour", "ssam composite", "present"}));

    Frame<TypeParam> g;
    g.opaquePass();
    ssam::ScreenSpaceAlphaMask hiddenSsam(*g.backend);
    QuadBatches hidden(*g.backend, {{3, 3, 4, 4, 0.5f, glm::vec4(1.0f)}});
    (void)g.backend->takeTimings();
    EXPECT_EQ(test_support::runSsam(hiddenSsam, g.targets(), viewOf(hidden)).passes,
              (std::vector<std::string>{"present"}));
    EXPECT_EQ(ssamPassesTimed(*g.backend), 0);
}

// Settings::depthMaskThreshold on the engine's backends: rt_depth keeps the foliage depth only
// where the composited mask reaches the threshold (the "ssam depth restore" pass); the
// composited colour is the same as without it. A alone: mask 0.4 -> 0.16 squared; the
// overlap: lerp(0.4, 0.6, 0.85) = 0.57 -> 0.325; B is cut by the colour pass (0.2 < 64/255).
TYPED_TEST_P(SsamCases, DepthMaskThresholdKeepsFoliageDepthOnlyWhereTheMaskReachesIt) {
    const auto run = [](float threshold) {
        auto f = std::make_unique<Frame<TypeParam>>();
        f->opaquePass();
        ssam::Settings settings;
        settings.depthMaskThreshold = threshold;
        ssam::ScreenSpaceAlphaMask ssam(*f->backend, settings);
        QuadBatches q(*f->backend, {kQuadA, kQuadB});
        const std::vector<std::string> passes = test_support::runSsam(ssam, f->targets(), viewOf(q)).passes;
        EXPECT_EQ(std::count(passes.begin(), passes.end(), "ssam depth restore"), threshold > 0.0f ? 1 : 0);
        return std::pair{f->backend->readback(f->opaque.color()), f->backend->readback(f->opaque.depth())};
    };
    const auto [paperColor, paperDepth] = run(0.0f);
    EXPECT_NEAR(paperDepth.at(kOnlyA, 4, 0), 0.3f, 1e-6f);
    const auto [color, depth] = run(0.2f);
    EXPECT_EQ(color.values, paperColor.values);
    EXPECT_NEAR(depth.at(kOnlyA, 4, 0), 1.0f, 1e-6f);    // 0.16 < 0.2: opaque depth
    EXPECT_NEAR(depth.at(kOverlap, 4, 0), 0.3f, 1e-6f);  // 0.325: A's depth
    EXPECT_NEAR(depth.at(kOnlyB, 4, 0), 1.0f, 1e-6f);
    const auto [lowColor, lowDepth] = run(0.1f);
    EXPECT_NEAR(lowDepth.at(kOnlyA, 4, 0), 0.3f, 1e-6f);  // 0.16 >= 0.1
}

REGISTER_TYPED_TEST_SUITE_P(SsamCases, CrossingQuadsGiveMaxAndAddMasks, ColourPassAlphaTestsAndWritesFoliageDepth,
                            CompositeFollowsListing32, SquaringAndLerpChangeTheResultAsTheFormulaSays,
                            ColourFadeKeepsALeafCrossingTheReferenceFromJumping, ColourBlurSoftensALeafMovingAPixel,
                            Rgba8AddMaskSaturatesWhereFloatMasksDoNot, OpaqueGeometryOccludesFoliageInEveryPass,
                            FoliageDepthOccludesLaterDrawsBehindNotInFront, NoFoliageInViewRunsNoPass,
                            ClosestSampleDepthResolveWithMsaaOpaquePass, MaskProgramIgnoresColour,
                            BadConfigurationIsRejectedWithTheKnobName,
                            FrameGraphRunsThreePassesWithFoliageAndNoneWithout,
                            DepthMaskThresholdKeepsFoliageDepthOnlyWhereTheMaskReachesIt);

}  // namespace ssam_cases
