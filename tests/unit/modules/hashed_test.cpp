// SPDX-License-Identifier: MIT
// Hashed alpha testing [Wyman & McGuire 2017] (transparency/hashed_alpha.hpp): the threshold's
// distribution, its stability (the same uv and instance give the same threshold across frames,
// camera moves and wind) and the coverage it gives.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "engine/render/frame_targets.hpp"
#include "engine/render/soft/soft_backend.hpp"
#include "transparency/create_technique.hpp"
#include "transparency/hashed_alpha.hpp"
#include "run_technique.hpp"

namespace {

using namespace engine::render;
using namespace transparency;

constexpr int kSize = 64;

// A card from (x0, y0) to (x1, y1) in world units (= NDC under an identity camera), uv 0..uvMax,
// white with alpha `alpha`.
std::vector<Vertex> card(float x0, float y0, float x1, float y1, float uvMax, float alpha) {
    auto v = [&](float x, float y, float u, float w) {
        Vertex vertex;
        vertex.position = {x, y, 0.5f};
        vertex.uv = {u, w};
        vertex.color = {1.0f, 1.0f, 1.0f, alpha};
        return vertex;
    };
    return {v(x0, y0, 0, 0), v(x1, y0, uvMax, 0),     v(x1, y1, uvMax, uvMax),
            v(x0, y0, 0, 0), v(x1, y1, uvMax, uvMax), v(x0, y1, 0, uvMax)};
}

struct Scene {
    std::vector<Vertex> vertices;
    std::vector<Instance> instances = std::vector<Instance>(1);  // one identity instance
    glm::mat4 viewProj{1.0f};
    std::uint64_t frameIndex = 0;
};

// The technique's frame over black: white where a fragment was kept.
std::vector<float> render(Backend& backend, Technique& technique, const Scene& scene) {
    const auto vbytes = std::as_bytes(std::span(scene.vertices));
    const auto ibytes = std::as_bytes(std::span(scene.instances));
    const BufferHandle vertices = backend.createBuffer({"card", BufferKind::Vertex, vbytes.size()}, vbytes);
    const BufferHandle instances = backend.createBuffer({"instances", BufferKind::Instance, ibytes.size()}, ibytes);
    FrameTargets opaque(backend, {kSize, kSize, technique.opaqueSamples(), Format::RGBA32F, CompareFunc::Less});
    backend.beginPass(opaque.passDesc({0, 0, 0, 1}));
    backend.endPass();
    FoliageDraw draw;
    draw.batch.vertices = vertices;
    draw.batch.count = std::uint32_t(scene.vertices.size());
    draw.batch.instances = instances;
    draw.batch.instanceCount = std::uint32_t(scene.instances.size());
    draw.batch.worldBounds = {{-4, -4, 0}, {4, 4, 1}};
    draw.instances = scene.instances;
    FoliageFrame frame;
    frame.viewProj = scene.viewProj;
    frame.light = unlitLight();
    frame.draws = std::span(&draw, 1);
    frame.frameIndex = scene.frameIndex;
    test_support::runTechnique(backend, technique, opaque, frame);
    const Readback r = backend.readback(opaque.color());
    backend.destroy(vertices);
    backend.destroy(instances);
    std::vector<float> red;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) red.push_back(r.at(x, y, 0));
    return red;
}

float keptFraction(const std::vector<float>& image, int x0, int y0, int x1, int y1) {
    int kept = 0, all = 0;
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) kept += image[std::size_t(y * kSize + x)] > 0.5f, ++all;
    return float(kept) / float(all);
}

glm::mat4 translation(float x, float y) {
    glm::mat4 m(1.0f);
    m[3] = {x, y, 0.0f, 1.0f};
    return m;
}

// Every ulp of a 24-bit hash is hit equally often, and the CDF correction turns the blend
// of two of them back into a uniform threshold: the histogram of thresholds over random uv
// and blend fractions is flat (each of 10 bins within 8% of a tenth, 5 standard deviations;
// the uncorrected blend at f = 0.5 puts 2% in the first bin).
TEST(Hashed, CorrectedThresholdIsUniformForAnyBlendFraction) {
    for (float f : {0.0f, 0.1f, 0.3f, 0.5f, 0.8f}) {
        std::vector<int> bins(10, 0);
        constexpr int kDraws = 40000;
        for (int i = 0; i < kDraws; ++i) {
            const float h0 = hashToUnit(pcg3d({std::uint32_t(i), 1u, 2u}).x);
            const float h1 = hashToUnit(pcg3d({std::uint32_t(i), 3u, 4u}).x);
            const float t = hashed_detail::uniformFromBlend((1.0f - f) * h0 + f * h1, f);
            ASSERT_GT(t, 0.0f);
            ASSERT_LE(t, 1.0f);
            ++bins[std::min(9, int(t * 10.0f))];
        }
        for (int b = 0; b < 10; ++b) EXPECT_NEAR(bins[b], kDraws / 10, kDraws / 10 * 0.08) << "f " << f << " bin " << b;
    }
}

// The blend factor: the fraction of log2 of the pixel scale, continuous (1 - m -> 0 as the
// scale reaches the next power of two), and the levels exact powers of two.
TEST(Hashed, LevelsAndBlendFactorFollowLog2OfThePixelScale) {
    EXPECT_FLOAT_EQ(hashed_detail::log2Mantissa(1.0f), 0.0f);
    EXPECT_FLOAT_EQ(hashed_detail::log2Mantissa(2.0f), 1.0f);
    for (float m = 1.0f; m < 2.0f; m += 0.01f) {
        EXPECT_NEAR(hashed_detail::log2Mantissa(m), std::log2(m), 0.005f) << m;
        EXPECT_LT(hashed_detail::log2Mantissa(m), hashed_detail::log2Mantissa(m + 0.01f)) << m;
    }
    const auto s = hashed_detail::splitLog2(0.375f);  // 2^-2 * 1.5
    EXPECT_EQ(s.exponent, -2);
    EXPECT_NEAR(s.fraction, std::log2(1.5f), 0.005f);
}

// A fixed reference keeps all or nothing of a leaf of uniform alpha; hashing keeps that
// fraction of its pixels, for isotropic and anisotropic scales and a derivative that is no
// power of two (the two hashes blended): within 0.03 over 48x48 pixels.
TEST(Hashed, KeepsTheFractionOfPixelsItsAlphaSays) {
    for (bool anisotropic : {false, true}) {
        auto backend = soft::createSoftBackend({.threads = 1});
        TechniqueOptions options;
        options.hashed.anisotropic = anisotropic;
        auto technique = createTechnique(TechniqueKind::Hashed, *backend, options);
        for (float alpha : {0.1f, 0.3f, 0.5f, 0.75f, 0.95f}) {
            Scene scene;
            scene.vertices = card(-1.0f, -1.0f, 1.0f, 1.0f, 1.37f, alpha);
            const float kept = keptFraction(render(*backend, *technique, scene), 8, 8, 56, 56);
            EXPECT_NEAR(kept, alpha, 0.03f) << "alpha " << alpha << (anisotropic ? " anisotropic" : "");
        }
        Scene zero;
        zero.vertices = card(-1.0f, -1.0f, 1.0f, 1.0f, 1.37f, 0.0f);
        EXPECT_EQ(keptFraction(render(*backend, *technique, zero), 0, 0, kSize, kSize), 0.0f)
            << "alpha 0 keeps nothing";
    }
}

// The pattern belongs to the leaf: the same frame again, a later frame (hashed's threshold
// does not change with the frame), the camera panned by whole pixels and the leaf's vertices
// moved by whole pixels (wind bends vertices, not the instance) all give the same pattern
// where the leaf is; another instance's transform (another plant) gives another pattern.
TEST(Hashed, SameUvAndInstanceGiveTheSameThresholdAcrossFramesCameraMovesAndWind) {
    auto backend = soft::createSoftBackend({.threads = 2});
    auto hashed = createTechnique(TechniqueKind::Hashed, *backend, {});
    const float pixel = 2.0f / kSize;  // one pixel in NDC, exact
    Scene still;
    still.vertices = card(-0.75f, -0.75f, 0.5f, 0.5f, 0.9f, 0.5f);
    still.instances = {Instance{translation(0.25f, 0.25f), glm::vec4(1.0f)}};
    const std::vector<float> base = render(*backend, *hashed, still);
    // The leaf covers pixels 16..47 in x and y.
    auto window = [](const std::vector<float>& image, int dx, int dy) {
        std::vector<float> w;
        for (int y = 16; y < 48; ++y)
            for (int x = 16; x < 48; ++x) w.push_back(image[std::size_t((y + dy) * kSize + x + dx)]);
        return w;
    };
    const float covered = keptFraction(base, 16, 16, 48, 48);
    ASSERT_GT(covered, 0.35f);
    ASSERT_LT(covered, 0.65f);

    Scene later = still;
    later.frameIndex = 17;
    EXPECT_EQ(render(*backend, *hashed, later), base) << "a later frame";

    Scene panned = still;  // the camera 5 pixels left: the leaf 5 pixels right on screen
    panned.viewProj = translation(5 * pixel, 3 * pixel);
    EXPECT_EQ(window(render(*backend, *hashed, panned), 5, -3), window(base, 0, 0)) << "camera pan";

    Scene wind = still;  // the vertices moved, the instance's transform unchanged
    for (Vertex& v : wind.vertices) v.position += glm::vec3(-4 * pixel, 2 * pixel, 0.0f);
    EXPECT_EQ(window(render(*backend, *hashed, wind), -4, -2), window(base, 0, 0)) << "wind";

    Scene other = still;  // another plant at the same place on screen: its own pattern
    other.instances = {Instance{translation(0.25f, 0.25f + 0x1p-20f), glm::vec4(1.0f)}};
    EXPECT_NE(render(*backend, *hashed, other), base) << "another instance";
}

}  // namespace
