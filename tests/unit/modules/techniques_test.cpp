// SPDX-License-Identifier: MIT
// Every transparency technique on synthetic quads whose expected pixels follow from a
// formula (modules/transparency): alpha test is binary, SSAM is [Hathaway 2010] §3.5.4, ...
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "engine/core/error.hpp"
#include "technique_fixture.hpp"
#include "two_quads.hpp"

namespace {

using namespace transparency;
using namespace transparency::testing;

std::unique_ptr<engine::render::Device> softBackend() { return soft::createSoftBackend({}); }

// One soft frame of `kind` over `foliage`: kept whole so a test can check the technique and
// the opaque targets after the frame as well as its colour.
struct SoftRun {
    std::unique_ptr<engine::render::Device> backend;
    std::unique_ptr<Technique> technique;
    TechniqueFrame frame;
    Readback result;

    SoftRun(TechniqueKind kind, int samples, const std::vector<Quad>& foliage, const TechniqueOptions& options = {})
        : backend(softBackend()), technique(createTechnique(kind, *backend, options)),
          frame(*backend, samples, foliage), result(frame.run(*technique)) {}
};

// The layers a technique asks the frame graph for, in order: what a host must allocate for it.
std::vector<std::string> intermediateLayers(const Technique& technique) {
    std::vector<std::string> names;
    for (const GraphTarget& t : technique.graphIntermediates()) names.push_back(t.layer);
    return names;
}

TEST(Techniques, EveryImplementedKindLeavesTheOpaqueFrameUnchangedWithoutFoliage) {
    for (TechniqueKind kind : allTechniques()) {
        auto backend = softBackend();
        std::unique_ptr<Technique> technique;
        try {
            technique = createTechnique(kind, *backend, {});
        } catch (const engine::Error&) {
            continue;  // not on this backend / not built: refusing is allowed, silently drawing is not
        }
        TechniqueFrame f(*backend, technique->opaqueSamples(), {});
        const Readback r = f.run(*technique);
        for (int y = 0; y < kSize; ++y)
            for (int x = 0; x < kSize; ++x)
                for (int c = 0; c < 4; ++c)
                    ASSERT_FLOAT_EQ(r.at(x, y, c), kOpaqueColor[c]) << techniqueName(kind) << " at " << x << "," << y;
    }
}

TEST(Techniques, AlphaTestIsBinaryAtTheReference) {
    for (int samples : {1, 4}) {
        auto backend = softBackend();
        auto technique = createTechnique(TechniqueKind::AlphaTest, *backend, {});
        EXPECT_EQ(technique->kind(), TechniqueKind::AlphaTest);
        TechniqueFrame f(*backend, samples, {kQuadA, kQuadB});
        const Readback r = f.run(*technique);
        // A (0.4 < 0.5) is discarded everywhere; B (0.6) is drawn opaque, alpha kept at 1.
        expectRgbNear(rgbAt(r, kOnlyA, kRow), glm::vec3(kOpaqueColor), 0.0f, "only A");
        expectRgbNear(rgbAt(r, kOverlap, kRow), {0.0f, 1.0f, 0.0f}, 0.0f, "overlap");
        expectRgbNear(rgbAt(r, kOnlyB, kRow), {0.0f, 1.0f, 0.0f}, 0.0f, "only B");
        EXPECT_EQ(r.at(kOnlyB, kRow, 3), 1.0f);
        // It writes foliage depth: B's depth where B was drawn.
        const Readback depth = backend->readback(f.opaque.depth());
        EXPECT_FLOAT_EQ(depth.at(kOnlyB, kRow, 0), kQuadB.depth);
        EXPECT_FLOAT_EQ(depth.at(kOnlyA, kRow, 0), 1.0f);
    }
}

TEST(Techniques, AlphaTestHonoursTheOpaqueDepth) {
    auto backend = softBackend();
    auto technique = createTechnique(TechniqueKind::AlphaTest, *backend, {});
    TechniqueFrame f(*backend, 1, {kQuadB});
    // An opaque wall nearer than B over the right half hides it there.
    const Readback r = f.run(*technique, {{0.0f, -1.0f, 1.0f, 1.0f, 0.1f, {1.0f, 1.0f, 1.0f, 1.0f}}});
    expectRgbNear(rgbAt(r, kOverlap - 1, kRow), {0.0f, 1.0f, 0.0f}, 0.0f, "in front of nothing");
    expectRgbNear(rgbAt(r, kOnlyB, kRow), {1.0f, 1.0f, 1.0f}, 0.0f, "behind the wall");
}

// Each technique refuses an option outside its range when it is created, not mid-frame.
TEST(Techniques, RejectBadOptions) {
    struct Case {
        TechniqueKind kind;
        void (*spoil)(TechniqueOptions&);
    };
    const Case cases[] = {
        {TechniqueKind::AlphaTest, [](TechniqueOptions& o) { o.alphaTestReference = 1.5f; }},
        {TechniqueKind::Wboit, [](TechniqueOptions& o) { o.wboitDepthScale = 0.0f; }},
    };
    for (const Case& c : cases) {
        auto backend = softBackend();
        TechniqueOptions options;
        c.spoil(options);
        EXPECT_THROW(createTechnique(c.kind, *backend, options), engine::Error) << techniqueName(c.kind);
    }
}

// [Hathaway 2010] §3.5.4 with Pure's defaults: mask = lerp(max, add, 0.85), squared; the colour
// pass keeps fragments with alpha >= 64/255 and the nearest one wins its depth test.
TEST(Techniques, SsamMatchesThePaperFormula) {
    const SoftRun run(TechniqueKind::Ssam, 2, {kQuadA, kQuadB});
    EXPECT_EQ(run.technique->kind(), TechniqueKind::Ssam);
    const Readback& r = run.result;
    auto q8 = [](float v) { return std::round(v * 255.0f) / 255.0f; };  // RGBA8 mask
    auto ssamMask = [&](float maxMask, float addMask) {
        const float m = std::clamp(q8(maxMask) + (q8(addMask) - q8(maxMask)) * 0.85f, 0.0f, 1.0f);
        return m * m;
    };
    const glm::vec3 opaque(kOpaqueColor);
    const glm::vec3 red(1, 0, 0), green(0, 1, 0);
    expectRgbNear(rgbAt(r, kOnlyA, kRow), glm::mix(opaque, red, ssamMask(0.4f, 0.4f)), 1e-5f, "only A");
    expectRgbNear(rgbAt(r, kOverlap, kRow), glm::mix(opaque, red, ssamMask(0.6f, 1.0f)), 1e-5f, "overlap");
    expectRgbNear(rgbAt(r, kOnlyB, kRow), glm::mix(opaque, green, ssamMask(0.6f, 0.6f)), 1e-5f, "only B");
    EXPECT_EQ(intermediateLayers(*run.technique), (std::vector<std::string>{"mask", "foliage"}));
}

// Drawn A (near) then B (far): the wrong order for "over" where they overlap.
TEST(Techniques, UnsortedBlendingComposesInSubmissionOrder) {
    const SoftRun run(TechniqueKind::BlendUnsorted, 1, {kQuadA, kQuadB});
    const Readback& r = run.result;
    const glm::vec3 opaque(kOpaqueColor);
    expectRgbNear(rgbAt(r, kOnlyA, kRow), over(kQuadA.color, opaque), 1e-6f, "only A");
    expectRgbNear(rgbAt(r, kOnlyB, kRow), over(kQuadB.color, opaque), 1e-6f, "only B");
    const glm::vec3 wrongOrder = over(kQuadB.color, over(kQuadA.color, opaque));
    expectRgbNear(rgbAt(r, kOverlap, kRow), wrongOrder, 1e-6f, "overlap");
    const glm::vec3 exact = over(kQuadA.color, over(kQuadB.color, opaque));
    EXPECT_GT(glm::length(wrongOrder - exact), 0.1f);  // the test can tell the orders apart
    EXPECT_EQ(r.at(kOverlap, kRow, 3), 1.0f);          // the frame's alpha is not written
}

TEST(Techniques, SortedBlendingIsExactForSeparateQuads) {
    const SoftRun run(TechniqueKind::BlendSorted, 1, {kQuadA, kQuadB});
    const Readback& r = run.result;
    const glm::vec3 opaque(kOpaqueColor);
    expectRgbNear(rgbAt(r, kOverlap, kRow), over(kQuadA.color, over(kQuadB.color, opaque)), 1e-6f, "overlap");
    expectRgbNear(rgbAt(r, kOnlyA, kRow), over(kQuadA.color, opaque), 1e-6f, "only A");
    // The opaque depth is left as it was (no depth write).
    EXPECT_FLOAT_EQ(run.backend->readback(run.frame.opaque.depth()).at(kOverlap, kRow, 0), 1.0f);
}

// One batch, three instances of a white quad tinted and moved in depth, submitted near to
// far: sorting must reorder inside the batch (per instance, not per batch).
TEST(Techniques, SortedBlendingSortsTheInstancesOfOneBatch) {
    for (CompareFunc func : {CompareFunc::Less, CompareFunc::Greater}) {
        auto backend = softBackend();
        TechniqueOptions options;
        options.depthFunc = func;
        auto technique = createTechnique(TechniqueKind::BlendSorted, *backend, options);
        const bool reverse = func == CompareFunc::Greater;
        auto depthOf = [&](float d) { return reverse ? 1.0f - d : d; };
        const glm::vec4 tints[] = {{1, 0, 0, 0.5f}, {0, 1, 0, 0.5f}, {0, 0, 1, 0.5f}};
        std::vector<Instance> instances;
        for (int i = 0; i < 3; ++i) {
            Instance inst;
            inst.model = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, depthOf(0.2f + 0.2f * float(i))));
            inst.tint = tints[i];
            instances.push_back(inst);
        }
        const auto bytes = std::as_bytes(std::span(instances));
        const BufferHandle buffer = backend->createBuffer({"instances", BufferKind::Instance, bytes.size()}, bytes);
        engine::render::FrameTargets opaque(*backend, {kSize, kSize, 1, Format::RGBA32F, func});
        ssam::testing::QuadBatches quad(*backend, {{-1.0f, -1.0f, 1.0f, 1.0f, 0.0f, glm::vec4(1.0f)}});
        FoliageDraw draw;
        draw.batch = quad.batches[0];
        draw.batch.instances = buffer;
        draw.batch.instanceCount = 3;
        draw.batch.worldBounds = {{-1, -1, 0}, {1, 1, 1}};
        draw.instances = instances;
        draw.meshBounds = quad.batches[0].worldBounds;
        backend->beginPass(opaque.passDesc(kOpaqueColor));
        backend->endPass();
        FoliageFrame frame;
        frame.light = unlitLight();
        frame.draws = std::span(&draw, 1);
        test_support::runTechnique(*backend, *technique, opaque, frame);
        const Readback r = backend->readback(opaque.color());
        const glm::vec3 exact = over(tints[0], over(tints[1], over(tints[2], glm::vec3(kOpaqueColor))));
        expectRgbNear(rgbAt(r, 7, 7), exact, 1e-6f, reverse ? "reverse-Z" : "conventional depth");
        backend->destroy(buffer);
    }
}

// A, B and a blue strip (alpha 0.9, nearest) over the bottom rows, drawn by an alpha-to-coverage
// technique `kind` into the `samples` per pixel it asks for.
Readback alphaToCoverageFrame(TechniqueKind kind, int samples) {
    auto backend = softBackend();
    auto technique = createTechnique(kind, *backend, {});
    EXPECT_EQ(technique->opaqueSamples(), samples) << techniqueName(kind);
    TechniqueFrame f(*backend, samples, {kQuadA, kQuadB, {-1.0f, -1.0f, 1.0f, -0.5f, 0.1f, {0, 0, 1, 0.9f}}});
    return f.run(*technique);
}

// 4 samples, round(alpha * 4) of them covered: A (0.4) covers 2, B (0.6) covers round(2.4) = 2,
// the same first two, where A is nearer and wins the depth test.
TEST(Techniques, AlphaToCoverageCoversRoundAlphaTimesFourSamples) {
    const Readback r = alphaToCoverageFrame(TechniqueKind::AlphaToCoverage, 4);
    const glm::vec3 opaque(kOpaqueColor);
    expectRgbNear(rgbAt(r, kOnlyA, kRow), glm::mix(opaque, {1, 0, 0}, 0.5f), 1e-6f, "only A");
    expectRgbNear(rgbAt(r, kOverlap, kRow), glm::mix(opaque, {1, 0, 0}, 0.5f), 1e-6f, "overlap");
    expectRgbNear(rgbAt(r, kOnlyB, kRow), glm::mix(opaque, {0, 1, 0}, 0.5f), 1e-6f, "only B");
    // The blue strip (alpha 0.9, nearest) covers round(3.6) = 4 samples: opaque blue.
    expectRgbNear(rgbAt(r, kOnlyB, 14), {0, 0, 1}, 1e-6f, "blue strip");
}

TEST(Techniques, AlphaToCoverageRefusesSingleSampledTargets) {
    auto backend = softBackend();
    auto technique = createTechnique(TechniqueKind::AlphaToCoverage, *backend, {});
    TechniqueFrame f(*backend, 1, {kQuadA});
    EXPECT_THROW(f.run(*technique), engine::Error);
}

// a2c8: round(alpha * 8) of 8 samples, the first ones in sample order, so that nearer layers
// of lower alpha leave the later samples to those behind: A (0.4) covers 3, B (0.6) 5.
TEST(Techniques, AlphaToCoverage8CoversRoundAlphaTimesEightSamples) {
    const Readback r = alphaToCoverageFrame(TechniqueKind::AlphaToCoverage8, 8);
    const glm::vec3 opaque(kOpaqueColor), red(1, 0, 0), green(0, 1, 0), blue(0, 0, 1);
    expectRgbNear(rgbAt(r, kOnlyA, kRow), (3.0f * red + 5.0f * opaque) / 8.0f, 1e-6f, "only A");
    expectRgbNear(rgbAt(r, kOverlap, kRow), (3.0f * red + 2.0f * green + 3.0f * opaque) / 8.0f, 1e-6f, "overlap");
    expectRgbNear(rgbAt(r, kOnlyB, kRow), (5.0f * green + 3.0f * opaque) / 8.0f, 1e-6f, "only B");
    // The blue strip (alpha 0.9, nearest) covers round(7.2) = 7 samples.
    expectRgbNear(rgbAt(r, kOnlyB, 14), (7.0f * blue + opaque) / 8.0f, 1e-6f, "blue strip");
}

// a2c-sharp and a2c8-sharp [Golus 2017]: vertex alpha is flat (a derivative of 0), so they
// cover as the alpha test at 0.5 does: A (0.4) nothing, B (0.6) every sample, where plain a2c
// covers 2 of 4 with each.
TEST(Techniques, AlphaToCoverageSharpWithFlatAlphaCoversAllOrNothingAtFourAndEightSamples) {
    for (TechniqueKind kind : {TechniqueKind::AlphaToCoverageSharp, TechniqueKind::AlphaToCoverage8Sharp}) {
        auto backend = softBackend();
        auto technique = createTechnique(kind, *backend, {});
        ASSERT_EQ(technique->opaqueSamples(), kind == TechniqueKind::AlphaToCoverageSharp ? 4 : 8);
        TechniqueFrame f(*backend, technique->opaqueSamples(), {kQuadA, kQuadB});
        const engine::render::Readback r = f.run(*technique);
        const std::string name(techniqueName(kind));
        expectRgbNear(rgbAt(r, kOnlyA, kRow), glm::vec3(kOpaqueColor), 1e-6f, (name + " only A").c_str());
        expectRgbNear(rgbAt(r, kOverlap, kRow), {0, 1, 0}, 1e-6f, (name + " overlap").c_str());
        expectRgbNear(rgbAt(r, kOnlyB, kRow), {0, 1, 0}, 1e-6f, (name + " only B").c_str());
    }
}

// McGuire & Bavoil 2013: with an identity projection every fragment has view depth 1, so
// eq. (7)'s depth factor g is the same for all and cancels in the average:
//   average = sum(C a^2) / sum(a^2),  revealage = prod(1 - a),
//   result  = average * (1 - revealage) + opaque * revealage.
TEST(Techniques, WboitMatchesThePaperFormula) {
    const SoftRun run(TechniqueKind::Wboit, 1, {kQuadA, kQuadB});
    const Readback& r = run.result;
    const glm::vec3 opaque(kOpaqueColor), red(1, 0, 0), green(0, 1, 0);
    auto wboit = [&](std::vector<glm::vec4> layers) {
        glm::vec3 sum(0.0f);
        float weight = 0.0f, reveal = 1.0f;
        for (const glm::vec4& c : layers) {
            sum += glm::vec3(c) * c.a * c.a;
            weight += c.a * c.a;
            reveal *= 1.0f - c.a;
        }
        return sum / weight * (1.0f - reveal) + opaque * reveal;
    };
    // RGBA16F accumulation and R16F revealage: half precision (11 significant bits).
    constexpr float kHalf = 2e-3f;
    expectRgbNear(rgbAt(r, kOnlyA, kRow), wboit({kQuadA.color}), kHalf, "only A");
    expectRgbNear(rgbAt(r, kOnlyB, kRow), wboit({kQuadB.color}), kHalf, "only B");
    const glm::vec3 both = wboit({kQuadA.color, kQuadB.color});
    expectRgbNear(rgbAt(r, kOverlap, kRow), both, kHalf, "overlap");
    // Order independent: the same in the other submission order.
    const SoftRun reversed(TechniqueKind::Wboit, 1, {kQuadB, kQuadA});
    expectRgbNear(rgbAt(reversed.result, kOverlap, kRow), both, kHalf, "overlap, B submitted first");
    // and not the exact "over" (the approximation is visible in this case).
    EXPECT_GT(glm::length(both - over(kQuadA.color, over(kQuadB.color, opaque))), 0.02f);
    EXPECT_EQ(run.technique->graphIntermediates().size(), 2u);
}

// Eq. (7)'s weight falls with view depth: nearer layers dominate the average.
TEST(Techniques, WboitWeightsNearerLayersMore) {
    const glm::mat4 perspective = glm::perspective(glm::radians(60.0f), 1.0f, 0.1f, 1000.0f);
    auto backend = softBackend();
    auto technique = createTechnique(TechniqueKind::Wboit, *backend, {});
    // Two full-screen quads in view space at distance 2 (red) and 50 (green), both alpha 0.5.
    auto quadAt = [](float distance, glm::vec4 color) {
        const float s = distance;  // wide enough to cover the view
        std::vector<Vertex> v(6);
        const glm::vec2 corners[6] = {{-s, -s}, {s, -s}, {s, s}, {-s, -s}, {s, s}, {-s, s}};
        for (int i = 0; i < 6; ++i) {
            v[i].position = {corners[i], -distance};
            v[i].color = color;
        }
        return v;
    };
    std::vector<Vertex> vertices = quadAt(50.0f, {0, 1, 0, 0.5f});
    const auto nearQuad = quadAt(2.0f, {1, 0, 0, 0.5f});
    vertices.insert(vertices.end(), nearQuad.begin(), nearQuad.end());
    const auto bytes = std::as_bytes(std::span(vertices));
    const BufferHandle buffer = backend->createBuffer({"quads", BufferKind::Vertex, bytes.size()}, bytes);
    engine::render::FrameTargets opaque(*backend, {kSize, kSize, 1, Format::RGBA32F, CompareFunc::Less});
    FoliageDraw draw;
    draw.batch.vertices = buffer;
    draw.batch.count = 12;
    draw.batch.worldBounds = {{-50, -50, -50}, {50, 50, -2}};
    draw.meshBounds = draw.batch.worldBounds;
    backend->beginPass(opaque.passDesc(kOpaqueColor));
    backend->endPass();
    FoliageFrame frame;
    frame.viewProj = perspective;
    frame.light = unlitLight();
    frame.draws = std::span(&draw, 1);
    test_support::runTechnique(*backend, *technique, opaque, frame);
    const glm::vec3 got = rgbAt(backend->readback(opaque.color()), 8, 8);
    auto g = [](float z) {
        const float v = 10.0f / (1e-5f + std::pow(z / 5.0f, 2.0f) + std::pow(z / 200.0f, 6.0f));
        return std::clamp(v, 1e-2f, 3e3f);
    };
    const float wNear = 0.25f * g(2.0f), wFar = 0.25f * g(50.0f);
    const glm::vec3 average = (glm::vec3(1, 0, 0) * wNear + glm::vec3(0, 1, 0) * wFar) / (wNear + wFar);
    const glm::vec3 want = average * 0.75f + glm::vec3(kOpaqueColor) * 0.25f;
    expectRgbNear(got, want, 3e-3f, "perspective");
    EXPECT_GT(got.r, 5.0f * got.g);  // the near red layer dominates
    backend->destroy(buffer);
}

// SSAM+: coverage = 1 - (1 - MAX)^(ADD / MAX) from a float mask (program.hpp
// CoverageModel::EqualLayers), exact for layers of equal alpha: three stacked quads of
// alpha 0.5 cover 1 - 0.5^3 = 0.875, where the paper's lerp(0.5, min(1.5, 1), 0.85)^2 gives
// 0.855 and the exact "over" of their colours would be reached only with exact colours.
TEST(Techniques, SsamPlusEstimatesTheCoverageOfEqualLayersExactly) {
    const glm::vec4 grey{0.5f, 0.5f, 0.5f, 0.5f};
    const std::vector<Quad> layers{{-1, -1, 1, 1, 0.3f, grey}, {-1, -1, 1, 1, 0.4f, grey}, {-1, -1, 0, 1, 0.5f, grey}};
    const SoftRun run(TechniqueKind::SsamPlus, 1, layers);
    EXPECT_EQ(run.technique->kind(), TechniqueKind::SsamPlus);
    const Readback& r = run.result;
    const glm::vec3 opaque(kOpaqueColor);
    // Left: three layers; right: two. All grey, so the colour pass's choice does not matter.
    expectRgbNear(rgbAt(r, 3, kRow), glm::mix(opaque, glm::vec3(0.5f), 0.875f), 1e-3f, "three layers");
    expectRgbNear(rgbAt(r, 12, kRow), glm::mix(opaque, glm::vec3(0.5f), 0.75f), 1e-3f, "two layers");
    // The exact reference agrees (equal-colour layers: over is exactly the coverage lerp).
    const SoftRun exact(TechniqueKind::Reference, 1, layers);
    expectRgbNear(rgbAt(r, 3, kRow), rgbAt(exact.result, 3, kRow), 1e-3f, "three layers vs reference");
    EXPECT_EQ(intermediateLayers(*run.technique),
              (std::vector<std::string>{"mask_max", "mask_add", "foliage", "front_layers"}));
}

// SSAM+'s front layers (SsamPlusOptions::frontLayers): the colour pass keeps B (alpha 0.6, above
// the reference of 128/255; A's 0.4 is below it) and the front-layers pass adds up A, in front of
// it. The overlap's colour is B's by B's alpha over A's; where only A is, the colour pass kept
// nothing and the colour is A's. Without the pass: B's, and the clear colour's.
TEST(Techniques, SsamPlusMixesInTheLayersInFrontOfTheKeptLeaf) {
    const glm::vec3 opaque(kOpaqueColor), red(1.0f, 0.0f, 0.0f), green(0.0f, 1.0f, 0.0f);
    const float overlapCoverage = 1.0f - std::pow(1.0f - 0.6f, 1.0f / 0.6f);  // ADD 1, MAX 0.6
    const SoftRun on(TechniqueKind::SsamPlus, 1, {kQuadA, kQuadB});
    expectRgbNear(rgbAt(on.result, kOverlap, kRow), glm::mix(opaque, 0.6f * green + 0.4f * red, overlapCoverage), 2e-3f,
                  "overlap");
    expectRgbNear(rgbAt(on.result, kOnlyA, kRow), glm::mix(opaque, red, 0.4f), 2e-3f, "only A");
    expectRgbNear(rgbAt(on.result, kOnlyB, kRow), glm::mix(opaque, green, 0.6f), 2e-3f, "only B");

    TechniqueOptions off;
    off.ssamPlus.frontLayers = false;
    const SoftRun without(TechniqueKind::SsamPlus, 1, {kQuadA, kQuadB}, off);
    expectRgbNear(rgbAt(without.result, kOverlap, kRow), glm::mix(opaque, green, overlapCoverage), 2e-3f,
                  "overlap, without");
    const float* clear = off.ssam.foliageClearColor;
    expectRgbNear(rgbAt(without.result, kOnlyA, kRow), glm::mix(opaque, glm::vec3(clear[0], clear[1], clear[2]), 0.4f),
                  2e-3f, "only A, without");
    EXPECT_EQ(intermediateLayers(*without.technique), (std::vector<std::string>{"mask_max", "mask_add", "foliage"}));
}

TEST(Techniques, SsamPlusExponentialModel) {
    TechniqueOptions options;
    options.ssamPlus.coverage = CoverageModel::Exponential;
    options.ssamPlus.maskPrecision = ssam::MaskPrecision::Rgba16f;
    options.ssamPlus.colorAlphaReference = 64.0f / 255.0f;  // below A's alpha, so A is the colour kept
    const SoftRun run(TechniqueKind::SsamPlus, 1, {kQuadA, kQuadB}, options);
    const Readback& r = run.result;
    const glm::vec3 opaque(kOpaqueColor);
    // Overlap: ADD = 1.0, coverage 1 - e^-1; the colour pass keeps A (nearest, 0.4 >= 64/255).
    expectRgbNear(rgbAt(r, kOverlap, kRow), glm::mix(opaque, glm::vec3(1, 0, 0), 1.0f - std::exp(-1.0f)), 1e-3f,
                  "overlap");
    expectRgbNear(rgbAt(r, kOnlyB, kRow), glm::mix(opaque, glm::vec3(0, 1, 0), 1.0f - std::exp(-0.6f)), 1e-3f,
                  "only B");
}

}  // namespace

namespace {

// KHR_materials_unlit: a batch marked unlit shows its base colour whatever the light; the
// same batch lit by a black light is black. Checked where the foliage is opaque in the result.
TEST(Techniques, UnlitBatchesIgnoreTheLight) {
    for (TechniqueKind kind :
         {TechniqueKind::AlphaTest, TechniqueKind::Ssam, TechniqueKind::BlendSorted, TechniqueKind::Reference}) {
        const Quad opaqueGreen{-0.25f, -1.0f, 1.0f, 1.0f, 0.6f, {0.0f, 1.0f, 0.0f, 1.0f}};
        glm::vec3 colour[2];
        for (bool unlit : {false, true}) {
            auto backend = softBackend();
            auto technique = createTechnique(kind, *backend, {});
            TechniqueFrame f(*backend, technique->opaqueSamples(), {opaqueGreen});
            f.draws[0].batch.unlit = unlit;
            f.opaquePass();
            FoliageFrame frame = f.frame();
            frame.light = {{0.0f, 0.0f, 1.0f}, glm::vec3(0.0f), glm::vec3(0.0f)};  // black
            test_support::runTechnique(*backend, *technique, f.opaque, frame);
            colour[unlit] = rgbAt(backend->readback(f.opaque.color()), kOnlyB, kRow);
        }
        expectRgbNear(colour[false], {0.0f, 0.0f, 0.0f}, 1e-6f, techniqueName(kind));
        expectRgbNear(colour[true], {0.0f, 1.0f, 0.0f}, 1e-6f, techniqueName(kind));
    }
}

}  // namespace
