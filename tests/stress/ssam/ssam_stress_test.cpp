// SPDX-License-Identifier: MIT
// Numerical stability of SSAM (label `stress`): depth complexity 1..4096 for every mask
// precision, alpha outside [0,1], NaN/Inf in vertex data and textures, and a 0.1 m .. 30 km
// depth range. The output must never hold NaN/Inf, nothing may wrap or go negative, and
// the degradation must be where the analysis below says it is.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include <Imath/half.h>

#include "engine/render/frame_targets.hpp"
#include "engine/render/projection.hpp"
#include "engine/render/soft/soft_backend.hpp"
#include "quad_scene.hpp"
#include "ssam/ssam.hpp"
#include "run_ssam.hpp"

namespace {

using namespace engine::render;
using ssam::testing::Quad;
using ssam::testing::QuadBatches;

constexpr int kSize = 8;
const glm::vec4 kOpaque{0.1f, 0.2f, 0.3f, 1.0f};
DirectionalLight unlit() { return {{0.0f, 0.0f, 1.0f}, glm::vec3(0.0f), glm::vec3(1.0f)}; }

struct Result {
    float maxMask, addMask;
    Readback color;
};

Result renderLayers(ssam::MaskPrecision precision, const std::vector<Quad>& quads,
                    std::uint8_t colorFormat = std::uint8_t(Format::RGBA8_UNORM)) {
    auto backend = soft::createSoftBackend({});
    engine::render::FrameTargets opaque(*backend, {kSize, kSize, 1, Format(colorFormat), CompareFunc::Less});
    backend->beginPass(opaque.passDesc(kOpaque));
    backend->endPass();
    ssam::Settings config;
    config.maskPrecision = precision;
    ssam::ScreenSpaceAlphaMask ssam(*backend, config);
    QuadBatches q(*backend, quads);
    const test_support::SsamRun run =
        test_support::runSsam(ssam, {opaque.color(), opaque.depth()}, {glm::mat4(1.0f), unlit(), q.batches}, true);
    Result r{0.0f, 0.0f, backend->readback(opaque.color())};
    if (!run.mask.values.empty()) {
        r.maxMask = run.mask.at(4, 4, 0);
        r.addMask = run.maskAdd.values.empty() ? run.mask.at(4, 4, 3) : run.maskAdd.at(4, 4, 0);
    }
    return r;
}

std::vector<Quad> layers(int count, float alpha) {
    std::vector<Quad> quads;
    for (int i = 0; i < count; ++i)
        quads.push_back({-1, -1, 1, 1, 0.01f + 0.98f * float(i) / float(count), {0.9f, 0.5f, 0.1f, alpha}});
    return quads;
}

void expectFiniteAndBounded(const Readback& r) {
    for (float v : r.values) {
        ASSERT_TRUE(std::isfinite(v));
        ASSERT_GE(v, 0.0f);
        ASSERT_LE(v, 1.0f);
    }
}

// The largest half-float value to which adding `a` still changes it: past it, a += a
// rounds back to the same value (a < half an ulp), so the float ADD mask stops growing.
float halfStagnation(float a) {
    float v = 0.0f;
    for (;;) {
        const float next = static_cast<float>(Imath::half(v + a));
        if (next == v) return v;
        v = next;
    }
}

TEST(SsamStress, DepthComplexityUpTo4096LayersForEveryPrecision) {
    const float alpha = 0.1f;  // stored in RGBA8 as 26/255
    for (const auto precision :
         {ssam::MaskPrecision::Rgba8, ssam::MaskPrecision::Rgba16f, ssam::MaskPrecision::Rg16f}) {
        for (const int n : {1, 2, 9, 10, 11, 64, 512, 4096}) {
            const Result r = renderLayers(precision, layers(n, alpha));
            SCOPED_TRACE(::testing::Message() << ssam::maskPrecisionName(precision) << " layers=" << n);
            expectFiniteAndBounded(r.color);
            EXPECT_GE(r.addMask, 0.0f);
            ASSERT_TRUE(std::isfinite(r.addMask));
            if (precision == ssam::MaskPrecision::Rgba8) {
                // Saturates once n * 26 >= 255, i.e. from 10 layers on (§3.5.2), and stays at 1.
                EXPECT_FLOAT_EQ(r.addMask, std::min(255.0f, 26.0f * n) / 255.0f);
                EXPECT_FLOAT_EQ(r.maxMask, 26.0f / 255.0f);
            } else {
                // Half floats accumulate exactly until the ulp outgrows the alpha, then stagnate.
                const float alphaHalf = static_cast<float>(Imath::half(alpha));
                EXPECT_LE(r.addMask, halfStagnation(alphaHalf));
                if (n <= 64) {
                    EXPECT_NEAR(r.addMask, n * alphaHalf, 0.01f * n * alphaHalf);
                }
                EXPECT_FLOAT_EQ(r.maxMask, alphaHalf);
            }
            if (n == 4096)
                std::printf("[ stress ] %-8s 4096 layers of alpha 0.1: ADD mask %.3f, MAX mask %.4f\n",
                            ssam::maskPrecisionName(precision), r.addMask, r.maxMask);
        }
    }
    std::printf("[ stress ] half-float ADD mask stagnates at %.1f for alpha 0.1\n",
                halfStagnation(static_cast<float>(Imath::half(0.1f))));
}

TEST(SsamStress, AlphaOutsideUnitRangeIsSaturated) {
    for (const auto precision : {ssam::MaskPrecision::Rgba8, ssam::MaskPrecision::Rgba16f}) {
        for (const float alpha : {-1.0f, 4.0f, 1e30f, -INFINITY, INFINITY}) {
            const Result r = renderLayers(precision, layers(3, alpha));
            SCOPED_TRACE(::testing::Message() << ssam::maskPrecisionName(precision) << " alpha=" << alpha);
            expectFiniteAndBounded(r.color);
            // Finite alphas saturate to [0,1]. An infinite vertex alpha becomes NaN when
            // interpolated (inf - inf in the plane set-up, as on GPUs) and NaN saturates to 0.
            const float saturated = std::isfinite(alpha) && alpha > 0.0f ? 1.0f : 0.0f;
            EXPECT_FLOAT_EQ(r.maxMask, saturated);
            EXPECT_FLOAT_EQ(r.addMask, precision == ssam::MaskPrecision::Rgba8 ? saturated : 3.0f * saturated);
        }
    }
}

TEST(SsamStress, NonFiniteVertexDataNeverReachesTheImage) {
    const float bad[] = {NAN, INFINITY, -INFINITY};
    for (const float b : bad) {
        std::vector<Quad> quads = layers(4, 0.5f);
        quads[0].x0 = b;                   // position
        quads[1].color = {b, b, b, 0.5f};  // colour
        quads[2].color.a = b;              // alpha
        quads[3].depth = b;                // depth
        const Result r = renderLayers(ssam::MaskPrecision::Rgba16f, quads, std::uint8_t(Format::RGBA16F));
        SCOPED_TRACE(::testing::Message() << "value=" << b);
        for (float v : r.color.values) ASSERT_TRUE(std::isfinite(v));
        EXPECT_TRUE(std::isfinite(r.addMask));
    }
}

TEST(SsamStress, NonFiniteTextureAlphaAndUvs) {
    auto backend = soft::createSoftBackend({});
    engine::render::FrameTargets opaque(*backend, {kSize, kSize, 1, Format::RGBA16F, CompareFunc::Less});
    backend->beginPass(opaque.passDesc(kOpaque));
    backend->endPass();
    // A float texture whose texels are NaN, +Inf and -Inf in every channel.
    const float texels[] = {NAN,       NAN,  NAN,  NAN,       INFINITY, INFINITY, INFINITY, INFINITY,
                            -INFINITY, 0.5f, 0.5f, -INFINITY, 0.5f,     0.5f,     0.5f,     0.5f};
    TextureDesc td;
    td.name = "hostile";
    td.width = td.height = 2;
    td.format = Format::RGBA32F;
    TextureData data{{std::as_bytes(std::span(texels))}};
    const TextureHandle texture = backend->createTexture(td, &data);
    auto vertices = ssam::testing::quadVertices({-1, -1, 1, 1, 0.5f, glm::vec4(1.0f)});
    vertices[0].uv = {NAN, INFINITY};
    vertices[2].uv = {-INFINITY, 1e30f};
    const auto bytes = std::as_bytes(std::span(vertices));
    const BufferHandle vb = backend->createBuffer({"quad", BufferKind::Vertex, bytes.size()}, bytes);
    engine::render::MaskedBatch batch;
    batch.vertices = vb;
    batch.count = 6;
    batch.baseColor.texture = texture;
    batch.worldBounds = {{-1, -1, 0.5f}, {1, 1, 0.5f}};
    ssam::ScreenSpaceAlphaMask ssam(*backend);
    test_support::runSsam(ssam, {opaque.color(), opaque.depth()}, {glm::mat4(1.0f), unlit(), std::span(&batch, 1)});
    for (float v : backend->readback(opaque.color()).values) ASSERT_TRUE(std::isfinite(v));
}

// Two foliage quads 10 m apart near the 30 km far plane, near plane 0.1 m: reverse-Z float
// depth keeps them apart, conventional float depth collapses them onto one value.
TEST(SsamStress, ReverseZResolvesThirtyKilometreVistas) {
    constexpr float kNear = 0.1f, kFar = 30000.0f;
    auto depthAt = [&](bool reverse, float distance) {
        const glm::mat4 p =
            reverse ? perspectiveReverseZ(1.0f, 1.0f, kNear, kFar) : perspectiveZeroToOne(1.0f, 1.0f, kNear, kFar);
        const glm::vec4 c = p * glm::vec4(0.0f, 0.0f, -distance, 1.0f);
        return c.z / c.w;
    };
    EXPECT_GT(depthAt(true, 29000.0f), depthAt(true, 29010.0f));    // nearer is larger under reverse-Z
    EXPECT_EQ(depthAt(false, 29000.0f), depthAt(false, 29010.0f));  // 1 - 3e-6 vs 1 - 3e-6: same float

    // Rendered: the nearer (red, 29 km) quad must win over the farther (green, 29.01 km) one
    // wherever the colour pass writes, whatever the submission order.
    for (const bool nearFirst : {true, false}) {
        auto backend = soft::createSoftBackend({});
        engine::render::FrameTargets opaque(*backend, {kSize, kSize, 1, Format::RGBA8_UNORM, CompareFunc::Greater});
        backend->beginPass(opaque.passDesc(kOpaque));
        backend->endPass();
        const glm::mat4 proj = perspectiveReverseZ(1.0f, 1.0f, kNear, kFar);
        auto quadAt = [](float distance, glm::vec4 color) {
            const float h = distance;  // fills the 1 rad view
            std::vector<engine::render::Vertex> v = ssam::testing::quadVertices({-h, -h, h, h, -distance, color});
            return v;
        };
        std::vector<engine::render::Vertex> near = quadAt(29000.0f, {1, 0, 0, 1}), far = quadAt(29010.0f, {0, 1, 0, 1});
        std::vector<std::vector<engine::render::Vertex>> order =
            nearFirst ? std::vector{near, far} : std::vector{far, near};
        std::vector<BufferHandle> buffers;
        std::vector<engine::render::MaskedBatch> batches;
        for (const auto& v : order) {
            const auto bytes = std::as_bytes(std::span(v));
            buffers.push_back(backend->createBuffer({"q", BufferKind::Vertex, bytes.size()}, bytes));
            engine::render::MaskedBatch b;
            b.vertices = buffers.back();
            b.count = 6;
            b.worldBounds = {{-3e4f, -3e4f, -3e4f}, {3e4f, 3e4f, -2.8e4f}};
            batches.push_back(b);
        }
        ssam::Settings config;
        config.depthTest = ssam::DepthTest::Greater;
        ssam::ScreenSpaceAlphaMask ssam(*backend, config);
        const Readback foliage =
            test_support::runSsam(ssam, {opaque.color(), opaque.depth()}, {proj, unlit(), batches}, true).foliage;
        EXPECT_FLOAT_EQ(foliage.at(4, 4, 0), 1.0f) << "near first: " << nearFirst;
        EXPECT_FLOAT_EQ(foliage.at(4, 4, 1), 0.0f) << "near first: " << nearFirst;
    }
}

}  // namespace
