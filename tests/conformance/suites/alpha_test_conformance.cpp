// SPDX-License-Identifier: MIT
// Alpha test in the GS sense (alpha_test.hpp): every CompareFunc x AlphaFailMode with the
// fragment alpha below, equal to and above the reference; colour RGB, colour alpha and
// depth are checked separately. Plus alpha-to-coverage at 1/2/4/8 samples.
#include <cmath>

#include "../backend_fixture.hpp"

namespace ssam::test {
namespace {

constexpr int kSize = 4;

int code(float v) { return int(std::lround(v * 255.0f)); }

TEST_P(AlphaTestConformance, EveryFuncAndFailMode) {
    const glm::vec4 clearColor{0.1f, 0.2f, 0.3f, 0.9f};
    const glm::vec3 sourceRgb{0.8f, 0.6f, 0.4f};
    const float clearDepth = 1.0f, fragmentDepth = 0.5f, reference = 0.5f;
    const auto [color, depth] = colorAndDepthTargets(kSize, kSize);
    const render::BufferHandle quad = vertexBuffer(pixelRect(kSize, kSize, 0, 0, kSize, kSize, fragmentDepth));
    int cases = 0;
    for (CompareFunc func : render::kAllCompareFuncs) {
        for (AlphaFailMode mode : render::kAllAlphaFailModes) {
            for (float alpha : {0.25f, 0.5f, 0.75f}) {
                const std::string what = std::string(render::compareFuncName(func)) + " " +
                                         render::alphaFailModeName(mode) + " alpha " + std::to_string(alpha);
                const AlphaTest test{true, func, reference, mode, false};
                const render::PipelineHandle pipeline =
                    flatPipeline({}, render::DepthState::testAndWrite(CompareFunc::Less), test);
                const render::PipelineInfo info = gfx().pipelineInfo(pipeline);
                pass(
                    color, clearColor, [&] { drawFlat(pipeline, quad, 6, glm::vec4(sourceRgb, alpha)); }, depth,
                    clearDepth);
                gfx().destroy(pipeline);
                if (!info.exact) {  // a backend that can only approximate the state says so
                    RecordProperty("approximated", info.note);
                    continue;
                }

                const bool passes = referenceCompare(func, alpha, reference);
                bool rgb = true, a = true, z = true;
                if (!passes) {
                    switch (mode) {
                        case AlphaFailMode::Keep: rgb = a = z = false; break;
                        case AlphaFailMode::FbOnly: z = false; break;
                        case AlphaFailMode::ZbOnly: rgb = a = false; break;
                        case AlphaFailMode::RgbOnly: a = z = false; break;
                    }
                }
                const auto [c, d] = readBoth(color, depth);
                for (int y = 0; y < kSize; ++y) {
                    for (int x = 0; x < kSize; ++x) {
                        for (int ch = 0; ch < 3; ++ch)
                            ASSERT_EQ(code(c.at(x, y, ch)), code(rgb ? sourceRgb[ch] : clearColor[ch]))
                                << what << ": RGB channel " << ch << " at " << x << "," << y;
                        ASSERT_EQ(code(c.at(x, y, 3)), code(a ? alpha : clearColor.a)) << what << ": alpha";
                        ASSERT_EQ(d.at(x, y, 0), z ? fragmentDepth : clearDepth) << what << ": depth";
                    }
                }
                ++cases;
            }
        }
    }
    RecordProperty("cases", std::to_string(cases));
}

// Where the test cannot change what is written, the pipeline says it dropped it.
TEST_P(AlphaTestConformance, DroppedWhereItCannotMatter) {
    auto dropped = [&](AlphaTest test, render::DepthState depth, std::uint8_t mask = render::WriteAll) {
        render::PipelineDesc desc;
        desc.name = "alpha";
        desc.alphaTest = test;
        desc.depth = depth;
        for (render::BlendState& b : desc.blend) b.writeMask = mask;
        return gfx().pipelineInfo(gfx().createPipeline(desc)).alphaTestDropped;
    };
    const auto write = render::DepthState::testAndWrite();
    const auto noWrite = render::DepthState::testOnly();
    // func Always: every fragment passes.
    for (AlphaFailMode mode : render::kAllAlphaFailModes)
        EXPECT_TRUE(dropped({true, CompareFunc::Always, 0.5f, mode, false}, write)) << render::alphaFailModeName(mode);
    // FbOnly writes the same as a pass unless depth is written.
    EXPECT_TRUE(dropped({true, CompareFunc::Less, 0.5f, AlphaFailMode::FbOnly, false}, noWrite));
    EXPECT_TRUE(dropped({true, CompareFunc::Less, 0.5f, AlphaFailMode::FbOnly, false}, render::DepthState::off()));
    EXPECT_FALSE(dropped({true, CompareFunc::Less, 0.5f, AlphaFailMode::FbOnly, false}, write));
    // Keep always matters (it discards), as does Never.
    EXPECT_FALSE(dropped({true, CompareFunc::Never, 0.5f, AlphaFailMode::Keep, false}, noWrite));
    EXPECT_FALSE(
        dropped({true, CompareFunc::GreaterEqual, 0.5f, AlphaFailMode::Keep, false}, render::DepthState::off()));
    // ZbOnly only withholds colour: irrelevant when no colour channel is written.
    EXPECT_TRUE(dropped({true, CompareFunc::Less, 0.5f, AlphaFailMode::ZbOnly, false}, write, 0));
    EXPECT_FALSE(dropped({true, CompareFunc::Less, 0.5f, AlphaFailMode::ZbOnly, false}, write));
    // RgbOnly withholds alpha and depth: irrelevant with neither written.
    EXPECT_TRUE(dropped({true, CompareFunc::Less, 0.5f, AlphaFailMode::RgbOnly, false}, noWrite, render::WriteRGB));
    EXPECT_FALSE(dropped({true, CompareFunc::Less, 0.5f, AlphaFailMode::RgbOnly, false}, noWrite));
    // A disabled test is not "dropped": there was nothing to drop.
    EXPECT_FALSE(dropped(AlphaTest::off(), write));
}

// A dropped test still renders what the test would have: FbOnly without depth writes
// writes colour for failing fragments too.
TEST_P(AlphaTestConformance, DroppedTestRendersTheSame) {
    const auto [color, depth] = colorAndDepthTargets(kSize, kSize);
    const render::BufferHandle quad = vertexBuffer(pixelRect(kSize, kSize, 0, 0, kSize, kSize, 0.25f));
    const render::PipelineHandle pipeline = flatPipeline(
        {}, render::DepthState::testOnly(), {true, CompareFunc::GreaterEqual, 0.5f, AlphaFailMode::FbOnly, false});
    ASSERT_TRUE(gfx().pipelineInfo(pipeline).alphaTestDropped);
    pass(
        color, glm::vec4(0.0f),
        [&] {
            drawFlat(pipeline, quad, 6, {1.0f, 0.0f, 1.0f, 0.2f});
        },
        depth, 1.0f);
    const auto [c, d] = readBoth(color, depth);
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            EXPECT_EQ(code(c.at(x, y, 0)), 255);
            EXPECT_EQ(code(c.at(x, y, 3)), code(0.2f));
            EXPECT_EQ(d.at(x, y, 0), 1.0f);
        }
}

render::AlphaTest alphaToCoverage() {
    render::AlphaTest test;
    test.alphaToCoverage = true;
    return test;
}

// Alpha-to-coverage: white with alpha a over black covers round(a * samples) samples, so the
// resolved value is that count / samples (RGB) and count * a / samples (alpha).
TEST_P(AlphaToCoverageConformance, CoveredSampleCount) {
    if (gfx().name() == "gles")
        GTEST_SKIP() << "OpenGL ES 3.0 has no gl_SampleMask: the GLES driver's alpha-to-coverage is "
                        "GL_SAMPLE_ALPHA_TO_COVERAGE, whose pattern is the implementation's (reported inexact)";
    // No a * samples lands on a .5 tie for 2, 4 or 8 samples (rounding of ties is the
    // implementation's choice).
    const float alphas[] = {0.0f, 0.05f, 0.1f, 0.2f, 0.3f, 0.45f, 0.55f, 0.7f, 0.9f, 1.0f};
    for (int samples : {2, 4, 8}) {
        const render::TextureHandle target = renderTarget(kSize, kSize, Format::RGBA32F, samples);
        const render::BufferHandle quad = vertexBuffer(pixelRect(kSize, kSize, 0, 0, kSize, kSize));
        const render::PipelineHandle pipeline = flatPipeline({}, {}, alphaToCoverage());
        for (float alpha : alphas) {
            pass(target, glm::vec4(0.0f), [&] { drawFlat(pipeline, quad, 6, {1.0f, 1.0f, 1.0f, alpha}); });
            const render::Readback r = gfx().readback(resolved(target));
            const int covered = int(std::lround(alpha * samples));
            for (int y = 0; y < kSize; ++y)
                for (int x = 0; x < kSize; ++x) {
                    EXPECT_NEAR(r.at(x, y, 0), float(covered) / samples, 1e-6)
                        << samples << " samples, alpha " << alpha << " at " << x << "," << y;
                    EXPECT_NEAR(r.at(x, y, 3), float(covered) * alpha / samples, 1e-6);
                }
        }
    }
}

// Same on an RGBA8 target (as foliage uses it), within 1 LSB.
TEST_P(AlphaToCoverageConformance, CoveredSampleCountRgba8) {
    if (gfx().name() == "gles")
        GTEST_SKIP() << "OpenGL ES 3.0 has no gl_SampleMask: the GLES driver's alpha-to-coverage is "
                        "GL_SAMPLE_ALPHA_TO_COVERAGE, whose pattern is the implementation's (reported inexact)";
    for (int samples : {2, 4, 8}) {
        const render::TextureHandle target = renderTarget(kSize, kSize, Format::RGBA8_UNORM, samples);
        const render::BufferHandle quad = vertexBuffer(pixelRect(kSize, kSize, 0, 0, kSize, kSize));
        const render::PipelineHandle pipeline = flatPipeline({}, {}, alphaToCoverage());
        for (float alpha : {0.1f, 0.3f, 0.7f, 0.9f}) {
            pass(target, glm::vec4(0.0f, 0.0f, 0.0f, 1.0f), [&] {
                drawFlat(pipeline, quad, 6, {1.0f, 1.0f, 1.0f, alpha});
            });
            const render::Readback r = gfx().readback(resolved(target));
            const int covered = int(std::lround(alpha * samples));
            EXPECT_NEAR(r.at(1, 2, 0), float(covered) / samples, 1.0f / 255.0f + 1e-6f)
                << samples << " samples, alpha " << alpha;
        }
    }
}

// At one sample alpha-to-coverage is ignored (as in GL): the fragment is written whole.
TEST_P(AlphaToCoverageConformance, IgnoredAtOneSample) {
    const render::TextureHandle target = renderTarget(kSize, kSize, Format::RGBA32F);
    const render::BufferHandle quad = vertexBuffer(pixelRect(kSize, kSize, 0, 0, kSize, kSize));
    const render::PipelineHandle pipeline = flatPipeline({}, {}, alphaToCoverage());
    pass(target, glm::vec4(0.0f), [&] { drawFlat(pipeline, quad, 6, {1.0f, 1.0f, 1.0f, 0.1f}); });
    const render::Readback r = gfx().readback(target);
    EXPECT_EQ(r.at(2, 2, 0), 1.0f);
    EXPECT_EQ(r.at(2, 2, 3), 0.1f);
}

// Alpha-to-coverage and the alpha test together: the test runs on the shaded alpha, and the
// surviving fragment still covers only round(a * samples) samples.
TEST_P(AlphaToCoverageConformance, CombinedWithAlphaTest) {
    const render::TextureHandle target = renderTarget(kSize, kSize, Format::RGBA32F, 4);
    const render::BufferHandle quad = vertexBuffer(pixelRect(kSize, kSize, 0, 0, kSize, kSize));
    const render::PipelineHandle pipeline =
        flatPipeline({}, {}, {true, CompareFunc::GreaterEqual, 0.5f, AlphaFailMode::Keep, true});
    pass(target, glm::vec4(0.0f), [&] { drawFlat(pipeline, quad, 6, {1.0f, 1.0f, 1.0f, 0.3f}); });
    EXPECT_EQ(gfx().readback(resolved(target)).at(0, 0, 0), 0.0f) << "alpha 0.3 fails >= 0.5";
    pass(target, glm::vec4(0.0f), [&] { drawFlat(pipeline, quad, 6, {1.0f, 1.0f, 1.0f, 0.7f}); });
    EXPECT_NEAR(gfx().readback(resolved(target)).at(0, 0, 0), 0.75f, 1e-6f) << "alpha 0.7 covers 3 of 4";
}

}  // namespace
}  // namespace ssam::test
