// SPDX-License-Identifier: MIT
// The soft backend's own contract beyond conformance: work counters (what was skipped is
// visible), creation-time simplification (PipelineInfo), clears and readback of every
// format, resource lifetime and per-pass timings.
#include <cmath>

#include "soft_test_util.hpp"

namespace ssam::test::soft {
namespace {

using engine::render::soft::SoftStats;

TEST(SoftBackend, NameAndOptions) {
    auto gfx = createSoftBackend({.threads = 2, .tileSize = 32, .debugChecks = true});
    EXPECT_EQ(gfx->name(), "soft");
    EXPECT_EQ(softDriver(*gfx).options().threads, 2);
    EXPECT_EQ(softDriver(*gfx).options().tileSize, 32);
    EXPECT_TRUE(softDriver(*gfx).options().debugChecks);
}

TEST(SoftBackend, StatsCountWork) {
    auto gfx = createSoftBackend({.threads = 1});
    const render::TextureHandle t = makeTarget(*gfx, 8, 8);
    const render::BufferHandle quad = makeVertices(*gfx, fullQuad());
    const render::PipelineHandle p = gfx->createPipeline({});
    EXPECT_EQ(softDriver(*gfx).stats().passes, 0u);
    gfx->beginPass(onePass(t));
    gfx->draw(flatDraw(p, quad, 6));
    gfx->draw(flatDraw(p, quad, 3));
    gfx->endPass();
    const SoftStats s = softDriver(*gfx).stats();
    EXPECT_EQ(s.passes, 1u);
    EXPECT_EQ(s.draws, 2u);
    EXPECT_EQ(s.trianglesIn, 3u);
    EXPECT_EQ(s.trianglesRasterized, 3u);
    EXPECT_EQ(s.trianglesDropped, 0u);
    // The second draw's triangle covers the 28 pixels below the diagonal and, by the
    // top-left rule, the 8 whose centres lie on it.
    EXPECT_EQ(s.pixelsShaded, 64u + 36u);
    EXPECT_EQ(s.pixelsTouched, s.pixelsShaded);
}

TEST(SoftBackend, CulledAndDepthRejectedWorkIsNotShaded) {
    auto gfx = createSoftBackend({.threads = 1});
    const render::TextureHandle t = makeTarget(*gfx, 8, 8);
    const render::TextureHandle z = makeTarget(*gfx, 8, 8, Format::D32F);
    const render::BufferHandle nearQuad = makeVertices(*gfx, fullQuad(0.2f));
    const render::BufferHandle farQuad = makeVertices(*gfx, fullQuad(0.8f));
    render::PipelineDesc desc = pipelineDesc("depth");
    desc.depth = render::DepthState::testAndWrite(CompareFunc::Less);
    const render::PipelineHandle p = gfx->createPipeline(desc);
    desc.raster.cull = render::CullMode::Front;  // fullQuad is counter-clockwise: front-facing
    const render::PipelineHandle culled = gfx->createPipeline(desc);
    gfx->beginPass(onePass(t, z));
    gfx->draw(flatDraw(p, nearQuad, 6));
    gfx->draw(flatDraw(p, farQuad, 6));  // behind: every pixel fails the depth test
    gfx->draw(flatDraw(culled, nearQuad, 6));
    gfx->endPass();
    const SoftStats s = softDriver(*gfx).stats();
    EXPECT_EQ(s.trianglesIn, 6u);
    EXPECT_EQ(s.trianglesRasterized, 4u);
    EXPECT_EQ(s.trianglesDropped, 2u) << "culled triangles count as dropped";
    EXPECT_EQ(s.pixelsShaded, 64u);
    EXPECT_EQ(s.pixelsTouched, 64u);
}

// A pipeline that writes no colour channel and no depth-relevant alpha test runs no program:
// depth-only work is counted as touched, not shaded.
TEST(SoftBackend, DepthOnlyPassShadesNothing) {
    auto gfx = createSoftBackend({.threads = 1});
    const render::TextureHandle t = makeTarget(*gfx, 8, 8);
    const render::TextureHandle z = makeTarget(*gfx, 8, 8, Format::D32F);
    const render::BufferHandle quad = makeVertices(*gfx, fullQuad(0.25f));
    render::PipelineDesc desc = pipelineDesc("prepass");
    desc.depth = render::DepthState::testAndWrite();
    for (BlendState& b : desc.blend) b.writeMask = 0;
    const render::PipelineHandle p = gfx->createPipeline(desc);
    gfx->beginPass(onePass(t, z));
    gfx->draw(flatDraw(p, quad, 6));
    gfx->endPass();
    EXPECT_EQ(softDriver(*gfx).stats().pixelsShaded, 0u);
    EXPECT_EQ(softDriver(*gfx).stats().pixelsTouched, 64u);
    EXPECT_EQ(gfx->readback(z).at(3, 3, 0), 0.25f);
    EXPECT_EQ(gfx->readback(t).at(3, 3, 0), 0.0f);
}

TEST(SoftBackend, PipelineInfoSimplification) {
    auto gfx = createSoftBackend({.threads = 1});
    auto info = [&](const render::PipelineDesc& d) { return gfx->pipelineInfo(gfx->createPipeline(d)); };
    render::PipelineDesc d = pipelineDesc("p");
    EXPECT_TRUE(info(d).blendIsPlainWrite);
    EXPECT_FALSE(info(d).alphaTestDropped);
    EXPECT_TRUE(info(d).exact);
    d.blend[2] = BlendState::alphaOver();
    EXPECT_FALSE(info(d).blendIsPlainWrite) << "any target that blends";
    d.blend[2].enabled = true;
    d.blend[2].srcRgb = d.blend[2].srcAlpha = BlendFactor::One;
    d.blend[2].dstRgb = d.blend[2].dstAlpha = BlendFactor::Zero;
    EXPECT_TRUE(info(d).blendIsPlainWrite) << "ONE/ZERO ADD is a plain write";
    d.blend[2].opAlpha = render::BlendOp::Max;
    EXPECT_FALSE(info(d).blendIsPlainWrite);

    d = pipelineDesc("alpha");
    d.alphaTest = {true, CompareFunc::Always, 0.5f, AlphaFailMode::Keep, false};
    EXPECT_TRUE(info(d).alphaTestDropped);
    d.alphaTest.func = CompareFunc::GreaterEqual;
    EXPECT_FALSE(info(d).alphaTestDropped);
    d.alphaTest.failMode = AlphaFailMode::FbOnly;
    EXPECT_TRUE(info(d).alphaTestDropped) << "no depth write: a failing fragment writes what a passing one does";
    d.depth = render::DepthState::testAndWrite();
    EXPECT_FALSE(info(d).alphaTestDropped);
    d.depth.write = false;
    EXPECT_TRUE(info(d).alphaTestDropped);
}

// Clears store the value by the format's rules; readback gives stored/255 for 8-bit
// formats (sRGB not decoded) and floats otherwise, one value per stored channel.
TEST(SoftBackend, ClearAndReadbackEveryFormat) {
    auto gfx = createSoftBackend({.threads = 1});
    const glm::vec4 clear{0.25f, 1.5f, -0.5f, 0.6f};
    struct Case {
        Format format;
        int channels;
        std::vector<float> expected;
    };
    const float srgbOfQuarter = std::round((1.055f * std::pow(0.25f, 1.0f / 2.4f) - 0.055f) * 255.0f) / 255.0f;
    const Case cases[] = {
        {Format::RGBA8_UNORM, 4, {64.0f / 255.0f, 1.0f, 0.0f, 153.0f / 255.0f}},
        {Format::RGBA8_SRGB, 4, {srgbOfQuarter, 1.0f, 0.0f, 153.0f / 255.0f}},
        {Format::R8_UNORM, 1, {64.0f / 255.0f}},
        {Format::RG8_UNORM, 2, {64.0f / 255.0f, 1.0f}},
        {Format::RGBA16F, 4, {0.25f, 1.5f, -0.5f, 0.60009765625f}},  // 0.6 to the nearest half
        {Format::RG16F, 2, {0.25f, 1.5f}},
        {Format::R16F, 1, {0.25f}},
        {Format::RGBA32F, 4, {0.25f, 1.5f, -0.5f, 0.6f}},
        {Format::R32F, 1, {0.25f}},
    };
    for (const Case& k : cases) {
        const render::TextureHandle t = makeTarget(*gfx, 3, 2, k.format);
        render::PassDesc p;
        p.name = "clear";
        p.color[0] = {t, render::LoadOp::Clear, clear};
        gfx->beginPass(p);
        gfx->endPass();
        const render::Readback r = gfx->readback(t);
        EXPECT_EQ(r.width, 3);
        EXPECT_EQ(r.height, 2);
        EXPECT_EQ(r.format, k.format);
        ASSERT_EQ(r.channels, k.channels) << formatName(k.format);
        ASSERT_EQ(r.values.size(), std::size_t(3 * 2 * k.channels));
        for (int c = 0; c < k.channels; ++c)
            EXPECT_EQ(r.at(2, 1, c), k.expected[c]) << formatName(k.format) << " " << c;
    }
    const render::TextureHandle z = makeTarget(*gfx, 2, 2, Format::D32F);
    render::PassDesc p;
    p.name = "depth";
    p.depth = {z, render::LoadOp::Clear, 0.375f};
    gfx->beginPass(p);
    gfx->endPass();
    EXPECT_EQ(gfx->readback(z).at(1, 1, 0), 0.375f);
}

// Load keeps the contents; a channel the format lacks is never written.
TEST(SoftBackend, LoadKeepsContentsAndNarrowFormatsDrawn) {
    auto gfx = createSoftBackend({.threads = 1});
    const render::TextureHandle rg = makeTarget(*gfx, 4, 4, Format::RG8_UNORM);
    const render::BufferHandle quad = makeVertices(*gfx, fullQuad());
    render::PipelineDesc d = pipelineDesc("add");
    d.blend[0].enabled = true;
    d.blend[0].srcRgb = d.blend[0].dstRgb = d.blend[0].srcAlpha = d.blend[0].dstAlpha = BlendFactor::One;
    const render::PipelineHandle add = gfx->createPipeline(d);
    render::PassDesc p;
    p.name = "rg";
    p.color[0] = {rg, render::LoadOp::Clear, {0.2f, 0.4f, 0.6f, 0.8f}};
    gfx->beginPass(p);
    gfx->draw(flatDraw(add, quad, 6, {0.1f, 0.1f, 0.1f, 0.1f}));
    gfx->endPass();
    p.color[0].load = render::LoadOp::Load;
    gfx->beginPass(p);
    gfx->draw(flatDraw(add, quad, 6, {0.1f, 0.1f, 0.1f, 0.1f}));
    gfx->endPass();
    const render::Readback r = gfx->readback(rg);
    EXPECT_NEAR(r.at(1, 1, 0), 0.4f, 1.0f / 255.0f);
    EXPECT_NEAR(r.at(1, 1, 1), 0.6f, 1.0f / 255.0f);
}

TEST(SoftBackend, TimingsPerPassInOrder) {
    auto gfx = createSoftBackend({.threads = 1});
    const render::TextureHandle t = makeTarget(*gfx, 4, 4);
    for (const char* name : {"one", "two", "three"}) {
        gfx->beginPass(onePass(t, {}, name));
        gfx->endPass();
    }
    const std::vector<render::PassTiming> timings = gfx->takeTimings();
    ASSERT_EQ(timings.size(), 3u);
    EXPECT_EQ(timings[0].pass, "one");
    EXPECT_EQ(timings[2].pass, "three");
    for (const render::PassTiming& t : timings) EXPECT_GE(t.milliseconds, 0.0);
    EXPECT_TRUE(gfx->takeTimings().empty()) << "taken timings are gone";
}

TEST(SoftBackend, DescribeAndBufferUpdates) {
    auto gfx = createSoftBackend({.threads = 1});
    render::TextureDesc desc;
    desc.name = "described";
    desc.width = 16;
    desc.height = 8;
    desc.format = Format::RGBA16F;
    desc.mipLevels = 3;
    desc.alpha = render::AlphaMode::Premultiplied;
    const render::TextureHandle t = gfx->createTexture(desc);
    const render::TextureDesc& got = gfx->describe(t);
    EXPECT_EQ(got.name, "described");
    EXPECT_EQ(got.width, 16);
    EXPECT_EQ(got.mipLevels, 3);
    EXPECT_EQ(got.alpha, render::AlphaMode::Premultiplied);

    // updateBuffer before a pass changes what the next draw uses.
    const render::TextureHandle target = makeTarget(*gfx, 4, 4);
    const render::BufferHandle vb = makeVertices(*gfx, fullQuad(0.5f));
    std::vector<render::Vertex> left = fullQuad(0.5f);
    for (render::Vertex& v : left) v.position.x = std::min(v.position.x, 0.0f);
    gfx->updateBuffer(vb, 0, bytesOf(left));
    const render::PipelineHandle p = gfx->createPipeline({});
    gfx->beginPass(onePass(target));
    gfx->draw(flatDraw(p, vb, 6));
    gfx->endPass();
    const render::Readback r = gfx->readback(target);
    EXPECT_EQ(r.at(1, 1, 0), 1.0f);
    EXPECT_EQ(r.at(2, 1, 0), 0.0f);
}

// debugChecks counts non-finite values stored into float targets.
TEST(SoftBackend, DebugChecksCountNonFiniteStores) {
    auto gfx = createSoftBackend({.threads = 1, .debugChecks = true});
    const render::TextureHandle t = makeTarget(*gfx, 2, 2, Format::RGBA32F);
    const render::BufferHandle quad = makeVertices(*gfx, fullQuad());
    const render::PipelineHandle p = gfx->createPipeline({});
    gfx->beginPass(onePass(t));
    gfx->draw(flatDraw(p, quad, 6, {INFINITY, 1.0f, std::nanf(""), 1.0f}));
    gfx->endPass();
    EXPECT_EQ(softDriver(*gfx).stats().nonFiniteStores, 2u * 4u);
}

}  // namespace
}  // namespace ssam::test::soft
