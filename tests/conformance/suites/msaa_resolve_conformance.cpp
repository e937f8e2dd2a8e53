// SPDX-License-Identifier: MIT
// MSAA resolve: colour resolves to the average of the samples, depth to the sample closest
// to the observer under the given depth function ([Hathaway 2010] §3.5.1), never an average;
// under DepthResolve::AnySample (every backend, GLES included) to one of the pixel's samples.
//
// The partial pixels come from a vertical edge exactly through the centre of column 2: with
// the standard sample patterns (D3D/Vulkan standard locations, which GL implementations use
// in practice) exactly half of a pixel's samples lie on each side for 2, 4 and 8 samples.
#include <cmath>
#include <string>

#include "../backend_fixture.hpp"

namespace ssam::test {
namespace {

constexpr int kWide = 6, kHigh = 4;
constexpr float kEdge = 2.5f;  // pixel centre of column 2

// Why the depth resolves are skipped on GLES.
constexpr const char* kNoSampleDepthOnGles =
    "OpenGL ES 3.0 cannot read a multisampled depth per sample: the device refuses the GLES driver's closest-sample "
    "resolve ([Hathaway 2010] §3.5.1; gles_differences checks the refusal, DepthIsOneOfItsSamples its AnySample)";

TEST_P(MsaaResolveConformance, ColourIsTheSampleAverage) {
    const glm::vec4 left{1.0f, 0.25f, 0.0f, 0.5f}, right{0.0f, 0.75f, 2.0f, 1.0f};
    for (int samples : {2, 4, 8}) {
        for (Format format : {Format::RGBA32F, Format::RGBA16F, Format::RGBA8_UNORM}) {
            const render::TextureHandle target = renderTarget(kWide, kHigh, format, samples);
            const render::PipelineHandle pipeline = flatPipeline();
            const render::BufferHandle l = vertexBuffer(pixelRect(kWide, kHigh, 0, 0, kEdge, kHigh));
            const render::BufferHandle r = vertexBuffer(pixelRect(kWide, kHigh, kEdge, 0, kWide, kHigh));
            pass(target, glm::vec4(0.0f), [&] {
                drawFlat(pipeline, l, 6, left);
                drawFlat(pipeline, r, 6, right);
            });
            const render::Readback out = gfx().readback(resolved(target));
            const bool unorm = format == Format::RGBA8_UNORM;
            const float tolerance = unorm ? 1.0f / 255.0f + 1e-6f : (format == Format::RGBA16F ? 1e-3f : 1e-6f);
            for (int y = 0; y < kHigh; ++y) {
                for (int x = 0; x < kWide; ++x) {
                    glm::vec4 l4 = left, r4 = right;
                    if (unorm) l4 = glm::clamp(l4, 0.0f, 1.0f), r4 = glm::clamp(r4, 0.0f, 1.0f);
                    const glm::vec4 expected = x < 2 ? l4 : (x > 2 ? r4 : (l4 + r4) * 0.5f);
                    for (int c = 0; c < 4; ++c)
                        EXPECT_NEAR(out.at(x, y, c), expected[c], tolerance)
                            << formatName(format) << " " << samples << "x pixel " << x << "," << y << " channel " << c;
                }
            }
        }
    }
}

// Untouched samples keep the clear value and take part in the average.
TEST_P(MsaaResolveConformance, UncoveredSamplesKeepTheClear) {
    for (int samples : {2, 4, 8}) {
        const render::TextureHandle target = renderTarget(kWide, kHigh, Format::RGBA32F, samples);
        const render::BufferHandle l = vertexBuffer(pixelRect(kWide, kHigh, 0, 0, kEdge, kHigh));
        const render::PipelineHandle pipeline = flatPipeline();
        pass(target, {0.0f, 0.0f, 1.0f, 1.0f}, [&] { drawFlat(pipeline, l, 6, {1, 0, 0, 1}); });
        const render::Readback out = gfx().readback(resolved(target));
        EXPECT_EQ(out.at(1, 1, 0), 1.0f);
        EXPECT_EQ(out.at(2, 1, 0), 0.5f) << samples;
        EXPECT_EQ(out.at(2, 1, 2), 0.5f) << samples;
        EXPECT_EQ(out.at(3, 1, 2), 1.0f);
    }
}

// Left of the edge depth 0.3, right of it 0.7: the split column resolves to 0.3 under Less
// and LessEqual, 0.7 under Greater and GreaterEqual; whole pixels resolve to their one value.
TEST_P(MsaaResolveConformance, DepthKeepsTheClosestSample) {
    if (gfx().name() == "gles") GTEST_SKIP() << kNoSampleDepthOnGles;
    for (int samples : {2, 4, 8}) {
        const render::TextureHandle depth = drawnDepth(kWide, kHigh, samples, 1.0f, CompareFunc::Always,
                                                       {{0, 0, kEdge, kHigh, 0.3f}, {kEdge, 0, kWide, kHigh, 0.7f}});
        for (CompareFunc func :
             {CompareFunc::Less, CompareFunc::LessEqual, CompareFunc::Greater, CompareFunc::GreaterEqual}) {
            const bool greater = func == CompareFunc::Greater || func == CompareFunc::GreaterEqual;
            const render::Readback out = gfx().readback(resolved(depth, func));
            for (int y = 0; y < kHigh; ++y)
                for (int x = 0; x < kWide; ++x) {
                    const float expected = x < 2 ? 0.3f : (x > 2 ? 0.7f : (greater ? 0.7f : 0.3f));
                    EXPECT_EQ(out.at(x, y, 0), expected)
                        << samples << "x " << render::compareFuncName(func) << " pixel " << x << "," << y;
                }
        }
    }
}

// Reverse-Z: clear 0 (far), only the left part drawn at 0.6. Greater keeps the drawn sample
// in the split column; Less would keep the far clear.
TEST_P(MsaaResolveConformance, DepthReverseZWithUncoveredSamples) {
    if (gfx().name() == "gles") GTEST_SKIP() << kNoSampleDepthOnGles;
    for (int samples : {2, 4, 8}) {
        const render::TextureHandle depth =
            drawnDepth(kWide, kHigh, samples, 0.0f, CompareFunc::Greater, {{0, 0, kEdge, kHigh, 0.6f}});
        const render::Readback greater = gfx().readback(resolved(depth, CompareFunc::Greater));
        const render::Readback less = gfx().readback(resolved(depth, CompareFunc::Less));
        EXPECT_EQ(greater.at(2, 0, 0), 0.6f) << samples;
        EXPECT_EQ(less.at(2, 0, 0), 0.0f) << samples;
        EXPECT_EQ(greater.at(4, 0, 0), 0.0f);
        EXPECT_EQ(greater.at(0, 0, 0), 0.6f);
    }
}

// AnySample: a whole pixel resolves to its one value, a split one to one of its two samples' values,
// never between them (an average would invent a surface; §3.5.1). Forward Z with both sides
// drawn, and reverse-Z with the right side left at the far clear.
TEST_P(MsaaResolveConformance, DepthIsOneOfItsSamples) {
    // The resolved depth of `depth` (drawn left `left`, right `right`) under `func`.
    const auto expectOneOfItsSamples = [&](render::TextureHandle depth, CompareFunc func, float left, float right,
                                           int samples) {
        const render::Readback out = gfx().readback(resolved(depth, func, render::DepthResolve::AnySample));
        for (int y = 0; y < kHigh; ++y)
            for (int x = 0; x < kWide; ++x) {
                const float value = out.at(x, y, 0);
                const std::string where = std::to_string(samples) + "x " + render::compareFuncName(func) + " pixel " +
                                          std::to_string(x) + "," + std::to_string(y);
                if (x == 2) EXPECT_TRUE(value == left || value == right) << where << ": " << value;
                else EXPECT_EQ(value, x < 2 ? left : right) << where;
            }
    };
    for (int samples : {2, 4, 8}) {
        // 4x everywhere (llvmpipe offers no 8x, lavapipe no 2x), every count on the soft backend.
        if (samples != 4 && gfx().name() != "soft") continue;
        expectOneOfItsSamples(drawnDepth(kWide, kHigh, samples, 1.0f, CompareFunc::Always,
                                         {{0, 0, kEdge, kHigh, 0.3f}, {kEdge, 0, kWide, kHigh, 0.7f}}),
                              CompareFunc::Less, 0.3f, 0.7f, samples);
        expectOneOfItsSamples(
            drawnDepth(kWide, kHigh, samples, 0.0f, CompareFunc::Greater, {{0, 0, kEdge, kHigh, 0.6f}}),
            CompareFunc::Greater, 0.6f, 0.0f, samples);
    }
}

// Resolve needs the same size and format and a single-sampled destination.
TEST_P(MsaaResolveConformance, MismatchedResolveIsRefused) {
    const render::TextureHandle source = renderTarget(kWide, kHigh, Format::RGBA8_UNORM, 4);
    const render::TextureHandle smaller = renderTarget(kWide - 1, kHigh, Format::RGBA8_UNORM);
    const render::TextureHandle otherFormat = renderTarget(kWide, kHigh, Format::RGBA16F);
    const render::TextureHandle multisampled = renderTarget(kWide, kHigh, Format::RGBA8_UNORM, 4);
    for (render::TextureHandle destination : {smaller, otherFormat, multisampled})
        EXPECT_THROW(gfx().resolve({source, destination}), engine::Error);
}

}  // namespace
}  // namespace ssam::test
