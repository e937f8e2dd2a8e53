// SPDX-License-Identifier: MIT
// Bad input to the soft backend: every misuse throws engine::Error with a message that says
// what was wrong, never crashes, and leaves the backend usable.
#include <cmath>
#include <limits>

#include "soft_test_util.hpp"
#include "ssam/composite_program.hpp"

namespace ssam::test::soft {
namespace {

using engine::render::Device;

class SoftBadInput : public ::testing::Test {
protected:
    std::unique_ptr<Device> gfx = createSoftBackend({.threads = 1});

    render::TextureDesc targetDesc(int width, int height, Format format = Format::RGBA8_UNORM) {
        render::TextureDesc d;
        d.name = "bad";
        d.width = width;
        d.height = height;
        d.format = format;
        d.usage = render::UsageRenderTarget;
        return d;
    }

    // A small valid pass still works and draws.
    void expectUsable() {
        const render::TextureHandle t = makeTarget(*gfx, 4, 4);
        const render::BufferHandle vb = makeVertices(*gfx, fullQuad());
        const render::PipelineHandle p = gfx->createPipeline({});
        gfx->beginPass(onePass(t));
        gfx->draw(flatDraw(p, vb, 6));
        gfx->endPass();
        EXPECT_EQ(gfx->readback(t).at(1, 1, 0), 1.0f) << "backend unusable after an error";
    }

    // The file's promise, kept after every test whatever bad input it gave.
    void TearDown() override { expectUsable(); }
};

TEST_F(SoftBadInput, TextureSizes) {
    expectError([&] { gfx->createTexture(targetDesc(0, 4)); }, "0x4 is empty");
    expectError([&] { gfx->createTexture(targetDesc(4, -1)); }, "is empty");
    expectError([&] { gfx->createTexture(targetDesc(16385, 1)); }, "exceeds the 16384 limit");
    expectError([&] { gfx->createTexture(targetDesc(1, 16385)); }, "exceeds the 16384 limit");
    expectError([&] { gfx->createTexture(targetDesc(std::numeric_limits<int>::max(), 1)); }, "limit");
    // 16384^2 RGBA32F is 4 GiB: refused before allocating.
    expectError([&] { gfx->createTexture(targetDesc(16384, 16384, Format::RGBA32F)); }, "1 GiB texture limit");
    render::TextureDesc msaa = targetDesc(16384, 16384, Format::RGBA8_UNORM);
    msaa.samples = 8;
    expectError([&] { gfx->createTexture(msaa); }, "1 GiB");
    // The name is in the message.
    expectError([&] { gfx->createTexture(targetDesc(0, 0)); }, "'bad'");
}

TEST_F(SoftBadInput, TextureSamplesMipsAndUsage) {
    render::TextureDesc d = targetDesc(8, 8);
    d.samples = 3;
    expectError([&] { gfx->createTexture(d); }, "3 samples (must be 1, 2, 4 or 8)");
    d.samples = 0;
    expectError([&] { gfx->createTexture(d); }, "samples");
    d.samples = 4;
    d.usage = render::UsageSampled;
    expectError([&] { gfx->createTexture(d); }, "multisampled textures must be render targets");
    d = targetDesc(8, 8, Format::D32F);
    d.usage = render::UsageSampled;
    expectError([&] { gfx->createTexture(d); }, "only for render targets");
    d = targetDesc(8, 8);
    d.mipLevels = 5;  // 8x8 has 4 levels
    expectError([&] { gfx->createTexture(d); }, "5 mip levels (1..4");
    d.mipLevels = 0;
    expectError([&] { gfx->createTexture(d); }, "mip levels");
    d.mipLevels = 2;
    d.samples = 4;
    expectError([&] { gfx->createTexture(d); }, "1 when multisampled");
}

TEST_F(SoftBadInput, TextureData) {
    render::TextureDesc d = targetDesc(2, 2);
    d.usage = render::UsageSampled;
    std::vector<std::byte> tooShort(15), right(16);
    render::TextureData data;
    data.levels = {tooShort};
    expectError([&] { gfx->createTexture(d, &data); }, "level 0 has 15 bytes, expected 16");
    data.levels = {right, right};
    expectError([&] { gfx->createTexture(d, &data); }, "2 levels of data for 1 mip levels");
    // 16F formats take 32-bit floats.
    d.format = Format::RGBA16F;
    std::vector<std::byte> halfSized(2 * 2 * 8);
    data.levels = {halfSized};
    expectError([&] { gfx->createTexture(d, &data); }, "expected 64");
}

TEST_F(SoftBadInput, Buffers) {
    expectError(
        [&] {
            gfx->createBuffer({"vb", render::BufferKind::Vertex, 0}, {});
        },
        "size 0 is not a positive multiple of 48");
    expectError(
        [&] {
            gfx->createBuffer({"vb", render::BufferKind::Vertex, 50}, {});
        },
        "not a positive multiple of 48");
    expectError([&] { gfx->createBuffer({"ib", render::BufferKind::Index, 6}, {}); }, "multiple of 4");
    expectError([&] { gfx->createBuffer({"inst", render::BufferKind::Instance, 81}, {}); }, "multiple of 80");
    std::vector<std::byte> bytes(40);
    expectError(
        [&] {
            gfx->createBuffer({"ib", render::BufferKind::Index, 8}, bytes);
        },
        "40 bytes given for a 8-byte buffer");
    const render::BufferHandle ib = gfx->createBuffer({"ib", render::BufferKind::Index, 8}, {});
    expectError([&] { gfx->updateBuffer(ib, 4, bytes); }, "overruns");
    expectError([&] { gfx->updateBuffer(ib, 9, std::span<const std::byte>(bytes).first(0)); }, "overruns");
    expectError([&] { gfx->updateBuffer(ib, std::numeric_limits<std::uint64_t>::max(), bytes); }, "overruns");
}

TEST_F(SoftBadInput, StaleAndNullHandles) {
    const render::TextureHandle t = makeTarget(*gfx, 4, 4);
    gfx->destroy(t);
    expectError([&] { gfx->describe(t); }, "texture handle 0:1 is stale");
    expectError([&] { gfx->readback(t); }, "stale");
    expectError([&] { gfx->destroy(t); }, "stale");
    expectError([&] { gfx->readback({}); }, "texture handle is null");
    // The slot is reused with a new generation: the old handle still fails, the new one works.
    const render::TextureHandle reused = makeTarget(*gfx, 4, 4);
    EXPECT_EQ(reused.index, t.index);
    EXPECT_NE(reused.generation, t.generation);
    expectError([&] { gfx->describe(t); }, "stale");
    EXPECT_EQ(gfx->describe(reused).width, 4);
    // Never-created handles.
    expectError([&] { gfx->describe(render::TextureHandle{99, 1}); }, "never created");
    expectError([&] { gfx->pipelineInfo(render::PipelineHandle{7, 3}); }, "pipeline handle 7:3");
    const render::BufferHandle b = makeVertices(*gfx, fullQuad());
    gfx->destroy(b);
    expectError([&] { gfx->updateBuffer(b, 0, {}); }, "buffer handle");
    // Stale handles in passes and draws.
    const render::PipelineHandle p = gfx->createPipeline({});
    gfx->destroy(p);
    expectError([&] { gfx->beginPass(onePass(t)); }, "stale");
    gfx->beginPass(onePass(reused));
    expectError([&] { gfx->draw(flatDraw(p, makeVertices(*gfx, fullQuad()), 6)); }, "pipeline handle");
    expectError([&] { gfx->draw(flatDraw(gfx->createPipeline({}), b, 6)); }, "buffer handle");
    gfx->endPass();
}

TEST_F(SoftBadInput, PassAttachments) {
    const render::TextureHandle a = makeTarget(*gfx, 8, 8, Format::RGBA8_UNORM, 1, "a");
    const render::TextureHandle small = makeTarget(*gfx, 8, 4, Format::RGBA8_UNORM, 1, "small");
    const render::TextureHandle msaa = makeTarget(*gfx, 8, 8, Format::RGBA8_UNORM, 4, "msaa");
    const render::TextureHandle depth = makeTarget(*gfx, 8, 8, Format::D32F, 1, "depth");
    const render::TextureHandle depthSmall = makeTarget(*gfx, 4, 4, Format::D32F, 1, "depthSmall");
    render::TextureDesc sampledOnly = targetDesc(8, 8);
    sampledOnly.name = "sampledOnly";
    sampledOnly.usage = render::UsageSampled;
    const render::TextureHandle s = gfx->createTexture(sampledOnly);

    render::PassDesc p = onePass(a);
    p.color[1] = {small};
    expectError([&] { gfx->beginPass(p); }, "'small' differs in size or sample count");
    p.color[1] = {msaa};
    expectError([&] { gfx->beginPass(p); }, "differs in size or sample count");
    expectError([&] { gfx->beginPass(onePass(a, depthSmall)); }, "'depthSmall' differs in size");
    expectError([&] { gfx->beginPass(onePass(s)); }, "'sampledOnly' is not a render target");
    expectError([&] { gfx->beginPass(onePass(depth)); }, "depth texture 'depth' bound as colour");
    expectError([&] { gfx->beginPass(onePass(a, a)); }, "'a' bound as depth is RGBA8_UNORM");
    expectError(
        [&] {
            render::PassDesc empty;
            empty.name = "empty";
            gfx->beginPass(empty);
        },
        "pass 'empty' has no attachments");
    // A depth-only pass is fine.
    render::PassDesc depthOnly;
    depthOnly.name = "depthOnly";
    depthOnly.depth = {depth};
    gfx->beginPass(depthOnly);
    gfx->endPass();
}

TEST_F(SoftBadInput, PassNesting) {
    const render::TextureHandle t = makeTarget(*gfx, 4, 4);
    const render::BufferHandle vb = makeVertices(*gfx, fullQuad());
    const render::PipelineHandle p = gfx->createPipeline({});
    expectError([&] { gfx->draw(flatDraw(p, vb, 6)); }, "draw outside a pass");
    expectError([&] { gfx->endPass(); }, "endPass without beginPass");
    gfx->beginPass(onePass(t, {}, "first"));
    expectError([&] { gfx->beginPass(onePass(t, {}, "second")); }, "pass 'second' begun while pass 'first' is open");
    gfx->endPass();
    expectError([&] { gfx->endPass(); }, "endPass without beginPass");
}

TEST_F(SoftBadInput, DrawValidation) {
    const render::TextureHandle t = makeTarget(*gfx, 4, 4);
    const render::BufferHandle vb = makeVertices(*gfx, fullQuad());  // 6 vertices
    const render::BufferHandle ib = makeIndices(*gfx, {0, 1, 2, 3, 4, 7});
    const render::PipelineHandle flat = gfx->createPipeline(pipelineDesc("flat"));
    render::PipelineDesc depthDesc = pipelineDesc("depthy");
    depthDesc.depth = render::DepthState::testAndWrite();
    const render::PipelineHandle depthy = gfx->createPipeline(depthDesc);
    const render::PipelineDesc litDesc = pipelineDesc("lit", render::ProgramKind::OpaqueLit);
    const render::PipelineHandle lit = gfx->createPipeline(litDesc);

    gfx->beginPass(onePass(t, {}, "p"));
    // Wrong parameter type for the program.
    render::DrawDesc d = flatDraw(lit, vb, 6);
    expectError([&] { gfx->draw(d); }, "pipeline 'lit' in pass 'p': parameters do not match program OpaqueLit");
    d = flatDraw(flat, vb, 6);
    d.params = render::SurfaceParams{};
    expectError([&] { gfx->draw(d); }, "parameters do not match program Flat");
    // Counts and ranges.
    expectError([&] { gfx->draw(flatDraw(flat, vb, 4)); }, "count 4 is not a multiple of 3");
    expectError([&] { gfx->draw(flatDraw(flat, vb, 9)); }, "vertices [0, 9) outside 'vertices' of 6");
    d = flatDraw(flat, vb, 6);
    d.first = 3;
    expectError([&] { gfx->draw(d); }, "vertices [3, 9)");
    d.first = std::numeric_limits<std::uint32_t>::max();  // first + count overflows 32 bits
    expectError([&] { gfx->draw(d); }, "outside");
    d = flatDraw(flat, vb, 6);
    d.indices = ib;
    expectError([&] { gfx->draw(d); }, "index 7 at position 5 >= vertex count 6");
    d.count = 9;
    expectError([&] { gfx->draw(d); }, "indices [0, 9) outside 'indices' of 6");
    // Buffers of the wrong kind.
    d = flatDraw(flat, ib, 3);
    expectError([&] { gfx->draw(d); }, "'indices' is not a vertex buffer");
    d = flatDraw(flat, vb, 3);
    d.indices = vb;
    expectError([&] { gfx->draw(d); }, "'vertices' is not an index buffer");
    // Instances.
    d = flatDraw(flat, vb, 6);
    d.instanceCount = 2;
    expectError([&] { gfx->draw(d); }, "instanceCount 2 without an instance buffer");
    std::vector<render::Instance> one(1);
    d.instances = gfx->createBuffer({"inst", render::BufferKind::Instance, sizeof(render::Instance)}, bytesOf(one));
    expectError([&] { gfx->draw(d); }, "2 instances exceed 'inst'");
    d.instances = vb;
    expectError([&] { gfx->draw(d); }, "is not an instance buffer");
    // Depth test without a depth target.
    expectError([&] { gfx->draw(flatDraw(depthy, vb, 6)); }, "depth test on but the pass has no depth target");
    gfx->endPass();
}

TEST_F(SoftBadInput, SampledTextures) {
    const render::TextureHandle t = makeTarget(*gfx, 4, 4);
    const render::TextureHandle msaa = makeTarget(*gfx, 4, 4, Format::RGBA8_UNORM, 4, "msaa");
    const render::TextureHandle depth = makeTarget(*gfx, 4, 4, Format::D32F, 1, "depth");
    const render::BufferHandle vb = makeVertices(*gfx, fullQuad());
    const render::PipelineDesc litDesc = pipelineDesc("lit", render::ProgramKind::MaskedLit);
    const render::PipelineHandle lit = gfx->createPipeline(litDesc);
    render::DrawDesc d = flatDraw(lit, vb, 6);
    gfx->beginPass(onePass(t, depth));
    render::SurfaceParams params;
    params.baseColor.texture = msaa;
    d.params = params;
    expectError([&] { gfx->draw(d); }, "samples multisampled texture 'msaa'");
    params.baseColor.texture = t;
    d.params = params;
    expectError([&] { gfx->draw(d); }, "samples 'target' while rendering into it");
    params.baseColor.texture = depth;
    d.params = params;
    expectError([&] { gfx->draw(d); }, "samples depth target 'depth'");
    gfx->endPass();
}

TEST_F(SoftBadInput, Pipelines) {
    render::PipelineDesc d = pipelineDesc("nanref");
    d.alphaTest = {true, render::CompareFunc::Less, std::nanf(""), render::AlphaFailMode::Keep, false};
    expectError([&] { gfx->createPipeline(d); }, "pipeline 'nanref': alpha reference is not finite");
    d = pipelineDesc("composite", gfx->createProgram(ssam::compositeProgram()));
    d.depth = render::DepthState::testOnly();
    expectError([&] { gfx->createPipeline(d); }, "full-screen program Composite cannot depth-test");
}

TEST_F(SoftBadInput, CompositeInputs) {
    const render::TextureHandle out = makeTarget(*gfx, 8, 8);
    const render::TextureHandle small = makeTarget(*gfx, 4, 4, Format::RGBA8_UNORM, 1, "small");
    const render::TextureHandle full = makeTarget(*gfx, 8, 8, Format::RGBA8_UNORM, 1, "full");
    const render::PipelineHandle p =
        gfx->createPipeline(pipelineDesc("composite", gfx->createProgram(ssam::compositeProgram())));
    render::DrawDesc d;
    d.pipeline = p;
    gfx->beginPass(onePass(out));
    ssam::CompositeParams c;
    c.foliage = full;
    c.mask = small;
    d.params = c;
    expectError([&] { gfx->draw(d); }, "input 'small' is smaller than the target");
    c.mask = {};
    d.params = c;
    expectError([&] { gfx->draw(d); }, "texture handle is null");
    c.mask = out;
    d.params = c;
    expectError([&] { gfx->draw(d); }, "while rendering into it");
    c.mask = full;
    c.maskLerp = std::nanf("");
    d.params = c;
    expectError([&] { gfx->draw(d); }, "maskLerp is not finite");
    gfx->endPass();
}

TEST_F(SoftBadInput, ResolveAndReadback) {
    const render::TextureHandle msaa = makeTarget(*gfx, 4, 4, Format::RGBA8_UNORM, 4, "msaa");
    const render::TextureHandle other = makeTarget(*gfx, 4, 4, Format::RGBA16F, 1, "other");
    const render::TextureHandle smaller = makeTarget(*gfx, 2, 4, Format::RGBA8_UNORM, 1, "smaller");
    expectError([&] { gfx->readback(msaa); }, "readback of 'msaa': multisampled; resolve it first");
    expectError([&] { gfx->resolve({msaa, other}); }, "resolve 'msaa' -> 'other': needs the same size and format");
    expectError([&] { gfx->resolve({msaa, smaller}); }, "needs the same size");
    expectError([&] { gfx->resolve({msaa, msaa}); }, "single-sampled destination");
    expectError([&] { gfx->resolve({msaa, {}}); }, "null");
}

TEST_F(SoftBadInput, Options) {
    expectError([] { createSoftBackend({.tileSize = 12}); }, "tileSize 12 must be a multiple of 8");
    expectError([] { createSoftBackend({.tileSize = 0}); }, "tileSize");
    expectError([] { createSoftBackend({.tileSize = 2048}); }, "tileSize");
}

// Destroying what the open pass uses is refused, either at once or when the pass executes;
// either way the error names the problem and the backend is not left stuck in the pass.
TEST_F(SoftBadInput, DestroyingWhatTheOpenPassUses) {
    const render::BufferHandle vb = makeVertices(*gfx, fullQuad());
    const render::PipelineHandle p = gfx->createPipeline({});
    auto destroyDuringPass = [&](auto destroyIt, render::PipelineHandle pipeline, render::BufferHandle vertices,
                                 render::TextureHandle target) {
        gfx->beginPass(onePass(target));
        gfx->draw(flatDraw(pipeline, vertices, 6));
        bool threw = false;
        try {
            destroyIt();
        } catch (const engine::Error&) {
            threw = true;
        }
        if (threw) {
            gfx->endPass();
        } else {
            expectError([&] { gfx->endPass(); }, "stale");
        }
        expectUsable();
    };
    const render::TextureHandle t = makeTarget(*gfx, 4, 4);
    destroyDuringPass([&] { gfx->destroy(t); }, p, vb, t);
    const render::BufferHandle temp = makeVertices(*gfx, fullQuad(), "temp");
    destroyDuringPass([&] { gfx->destroy(temp); }, p, temp, makeTarget(*gfx, 4, 4));
    const render::PipelineHandle tempPipeline = gfx->createPipeline(pipelineDesc("temp"));
    destroyDuringPass([&] { gfx->destroy(tempPipeline); }, tempPipeline, vb, makeTarget(*gfx, 4, 4));
}

}  // namespace
}  // namespace ssam::test::soft
