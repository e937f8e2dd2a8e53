// SPDX-License-Identifier: MIT
// The programs and soft-backend hooks the transparency techniques added
// (programs.hpp: WboitAccumulate, WboitResolve, CoverageComposite, CoverageBlurComposite; SoftBackend::setFragmentSink): bad
// input is refused with engine::Error, and every technique is deterministic for any thread
// count (the soft backend's promise, seeds of the goldens).
#include <gtest/gtest.h>

#include "draws.hpp"         // tests/support
#include "expect_error.hpp"  // tests/support

#include <algorithm>
#include <cmath>
#include <limits>

#include "engine/core/error.hpp"
#include "ssam/composite_program.hpp"
#include "technique_fixture.hpp"
#include "transparency/programs.hpp"

namespace {

using namespace transparency;
using namespace transparency::testing;
using ssam::testing::drawFullscreenInto;

TextureHandle texture(Backend& b, int size, Format format, std::uint8_t usage = UsageSampled | UsageRenderTarget) {
    TextureDesc t;
    t.name = "t";
    t.width = t.height = size;
    t.format = format;
    t.usage = usage;
    return b.createTexture(t);
}

TEST(TransparencyPrograms, FullscreenKindsRefuseMissingOrSmallInputs) {
    auto b = soft::createSoftBackend({});
    const TextureHandle target = texture(*b, 8, Format::RGBA32F);
    const TextureHandle small = texture(*b, 4, Format::RGBA16F);
    const TextureHandle good = texture(*b, 8, Format::RGBA16F);
    const ProgramHandle resolve = b->createProgram(wboitResolveProgram());
    const ProgramHandle coverage = b->createProgram(coverageCompositeProgram());
    EXPECT_THROW(drawFullscreenInto(*b, resolve, WboitResolveParams{{}, good}, target), engine::Error);
    EXPECT_THROW(drawFullscreenInto(*b, resolve, WboitResolveParams{good, small}, target), engine::Error);
    EXPECT_THROW(
        drawFullscreenInto(*b, coverage, CoverageCompositeParams{good, {}, {}, CoverageModel::EqualLayers}, target),
        engine::Error);
    EXPECT_THROW(drawFullscreenInto(*b, coverage, CoverageCompositeParams{good, good, {}, CoverageModel(7)}, target),
                 engine::Error);
    // Parameters of another kind.
    EXPECT_THROW(drawFullscreenInto(*b, resolve, ssam::CompositeParams{good, good, {}, 0.85f, true}, target),
                 engine::Error);
    EXPECT_NO_THROW(drawFullscreenInto(*b, resolve, WboitResolveParams{good, good}, target));
}

// Non-finite accumulation (hostile HDR data) composites as black, never NaN.
TEST(TransparencyPrograms, WboitResolveNeverOutputsNaN) {
    auto b = soft::createSoftBackend({});
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    const std::vector<float> accumulation = {nan, inf, 1.0f, 0.0f};  // one texel: rgb = (NaN, Inf, 1), weight 0
    const std::vector<float> revealage = {nan};
    TextureDesc t;
    t.name = "acc";
    t.width = t.height = 1;
    t.format = Format::RGBA32F;
    TextureData data;
    data.levels.push_back(std::as_bytes(std::span(accumulation)));
    const TextureHandle acc = b->createTexture(t, &data);
    t.format = Format::R32F;
    data.levels[0] = std::as_bytes(std::span(revealage));
    const TextureHandle rev = b->createTexture(t, &data);
    const TextureHandle target = texture(*b, 1, Format::RGBA32F);
    drawFullscreenInto(*b, b->createProgram(wboitResolveProgram()), WboitResolveParams{acc, rev}, target);
    const Readback r = b->readback(target);
    for (float v : r.values) EXPECT_TRUE(std::isfinite(v));
}

// SSAM+'s blurred composite: the colour is the 1-2-1 x 1-2-1 average of the foliage texels
// the colour pass wrote (alpha > 0) around the pixel and inside the target, the coverage the
// unblurred composite's; with nothing written around it, the pixel's own texel; non-finite
// colour comes out as 0.
TEST(TransparencyPrograms, BlurCompositeAveragesTheWrittenNeighboursByTheirAlpha) {
    auto b = soft::createSoftBackend({});
    constexpr int n = 4;
    std::vector<float> foliage(n * n * 4, 0.0f), mask(n * n * 4, 0.0f);
    auto at = [&](std::vector<float>& v, int x, int y) { return v.begin() + (y * n + x) * 4; };
    const float values[n * n] = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16};
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const float v = values[y * n + x] / 16.0f;
            const bool written = !(x == 1 && y == 1) && !(x == 3 && y == 3);  // two texels the pass missed
            // Leaves covering all, half or a fifth of their pixel, and one alpha above 1 (weighs as 1).
            const float alpha = (x + y) % 3 == 0 ? 1.0f : (x + y) % 3 == 1 ? 0.5f : 0.2f;
            const float stored = x == 2 && y == 0 ? 3.0f : alpha;
            std::copy_n(std::vector<float>{v, v / 2, v / 4, written ? stored : 0.0f}.begin(), 4, at(foliage, x, y));
            std::copy_n(std::vector<float>{0.5f, 0.0f, 0.0f, 1.0f}.begin(), 4, at(mask, x, y));  // two layers of 0.5
        }
    at(foliage, 0, 3)[0] = std::numeric_limits<float>::quiet_NaN();  // poisons its neighbours' red
    TextureDesc t;
    t.name = "foliage";
    t.width = t.height = n;
    t.format = Format::RGBA32F;
    t.usage = UsageSampled;
    TextureData data;
    data.levels.push_back(std::as_bytes(std::span(foliage)));
    const TextureHandle f = b->createTexture(t, &data);
    data.levels[0] = std::as_bytes(std::span(mask));
    const TextureHandle m = b->createTexture(t, &data);
    const TextureHandle target = texture(*b, n, Format::RGBA32F);
    drawFullscreenInto(*b, b->createProgram(coverageBlurCompositeProgram()),
                       CoverageCompositeParams{f, m, {}, CoverageModel::EqualLayers}, target);
    const Readback r = b->readback(target);
    auto expected = [&](int x, int y) {
        glm::vec3 sum(0.0f);
        float weights = 0.0f;
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
                const int u = x + dx, v = y + dy;
                if (u < 0 || v < 0 || u >= n || v >= n || at(foliage, u, v)[3] == 0.0f) continue;
                const float alpha = std::min(at(foliage, u, v)[3], 1.0f);
                const float w = float((2 - dx * dx) * (2 - dy * dy)) * (alpha * std::sqrt(alpha));
                sum += w * glm::vec3(at(foliage, u, v)[0], at(foliage, u, v)[1], at(foliage, u, v)[2]);
                weights += w;
            }
        return sum / weights;
    };
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            SCOPED_TRACE(std::to_string(x) + "," + std::to_string(y));
            const float* out = &r.values[std::size_t(y * n + x) * 4];
            const glm::vec3 e = expected(x, y);
            for (int c = 0; c < 3; ++c) {
                if (std::isfinite(e[c])) EXPECT_FLOAT_EQ(out[c], e[c]) << "channel " << c;
                else EXPECT_EQ(out[c], 0.0f) << "channel " << c;  // a NaN neighbour: the composite's 0
            }
            EXPECT_FLOAT_EQ(out[3], 0.75f);  // 1 - (1 - 0.5)^2: two layers of 0.5
        }
}

// SSAM+'s front layers (CoverageCompositeParams::frontLayers), in both composites: the kept leaf's
// colour by its alpha (clamped to 1) over the mean of the layers in front, (sum a * C) / (sum a);
// the kept colour alone where no layer is in front; non-finite sums as 0. The foliage is one
// colour, so the blurred composite's average is that colour too.
TEST(TransparencyPrograms, CompositesMixInTheFrontLayersByTheKeptLeafsAlpha) {
    auto b = soft::createSoftBackend({});
    constexpr int n = 5;
    const glm::vec3 kept(0.8f, 0.4f, 0.2f), front(0.1f, 0.9f, 0.5f);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float keptAlpha[n] = {0.75f, 3.0f, 0.0f, 0.5f, 0.5f};   // 3: weighs as 1; 0: nothing kept
    const float frontWeight[n] = {0.3f, 0.3f, 0.6f, 0.0f, 0.5f};  // 0: no layer in front
    std::vector<float> foliage, mask, layers;
    for (int x = 0; x < n; ++x) {
        foliage.insert(foliage.end(), {kept.r, kept.g, kept.b, keptAlpha[x]});
        mask.insert(mask.end(), {0.5f, 0.0f, 0.0f, 1.0f});
        const float w = frontWeight[x];
        layers.insert(layers.end(), {x == 4 ? nan : front.r * w, front.g * w, front.b * w, w});
    }
    TextureDesc t;
    t.name = "inputs";
    t.width = n;
    t.height = 1;
    t.format = Format::RGBA32F;
    t.usage = UsageSampled;
    auto make = [&](const std::vector<float>& texels) {
        TextureData data;
        data.levels.push_back(std::as_bytes(std::span(texels)));
        return b->createTexture(t, &data);
    };
    CoverageCompositeParams params{make(foliage), make(mask), {}, CoverageModel::EqualLayers};
    params.frontLayers = make(layers);
    t.usage = UsageSampled | UsageRenderTarget;
    const TextureHandle target = b->createTexture(t);
    for (bool blur : {false, true}) {
        drawFullscreenInto(*b, b->createProgram(blur ? coverageBlurCompositeProgram() : coverageCompositeProgram()),
                           params, target);
        const Readback r = b->readback(target);
        const glm::vec3 expected[n] = {kept * 0.75f + front * 0.25f,
                                       kept,
                                       front,
                                       kept,
                                       {0.0f, kept.g * 0.5f + front.g * 0.5f, kept.b * 0.5f + front.b * 0.5f}};
        for (int x = 0; x < n; ++x)
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(r.values[std::size_t(x) * 4 + c], expected[x][c], 1e-6f)
                    << (blur ? "blurred" : "plain") << " composite, pixel " << x << " channel " << c;
    }
}

struct NullSink final : soft::FragmentSink {
    void add(int, int, const soft::CapturedFragment&) override {}
};

TEST(TransparencyPrograms, FragmentCaptureNeedsASingleSampledDepthTestedPass) {
    auto b = soft::createSoftBackend({});
    ssam::testing::QuadBatches quad(*b, {{-1, -1, 1, 1, 0.5f, glm::vec4(1.0f)}});
    NullSink sink;
    for (int samples : {1, 4})
        for (bool depthTest : {false, true}) {
            engine::render::FrameTargets opaque(*b, {8, 8, samples, Format::RGBA8_UNORM, CompareFunc::Less});
            PipelineDesc p;
            p.name = "capture";
            p.program = ProgramKind::MaskedLit;
            if (depthTest) p.depth = DepthState::testOnly();
            const PipelineHandle pipeline = b->createPipeline(p);
            b->fragmentCapture()->setFragmentSink(&sink);
            b->beginPass(opaque.passDesc(glm::vec4(0.0f)));
            DrawDesc d;
            d.pipeline = pipeline;
            d.params = SurfaceParams{};
            d.vertices = quad.batches[0].vertices;
            d.count = 6;
            if (samples == 1 && depthTest) EXPECT_NO_THROW(b->draw(d));
            else EXPECT_THROW(b->draw(d), engine::Error) << samples << " samples, depth test " << depthTest;
            b->endPass();
            b->fragmentCapture()->setFragmentSink(nullptr);
            b->destroy(pipeline);
        }
}

TEST(TransparencyPrograms, EveryTechniqueIsTheSameForAnyThreadCount) {
    const std::vector<Quad> foliage = {{-1.0f, -1.0f, 0.25f, 1.0f, 0.3f, {1.0f, 0.2f, 0.0f, 0.4f}},
                                       {-0.25f, -1.0f, 1.0f, 0.5f, 0.6f, {0.0f, 1.0f, 0.5f, 0.6f}},
                                       {-0.5f, -0.5f, 0.5f, 1.0f, 0.45f, {0.2f, 0.3f, 1.0f, 0.75f}}};
    for (TechniqueKind kind : allTechniques()) {
        std::vector<std::vector<float>> images;
        for (int threads : {1, 2}) {
            auto b = soft::createSoftBackend({.threads = threads, .tileSize = 8});
            auto technique = createTechnique(kind, *b, {});
            TechniqueFrame f(*b, technique->opaqueSamples(), foliage);
            images.push_back(f.run(*technique).values);
        }
        EXPECT_EQ(images[0], images[1]) << techniqueName(kind);
    }
}

}  // namespace
