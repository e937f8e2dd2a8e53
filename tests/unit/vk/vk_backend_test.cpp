// SPDX-License-Identifier: MIT
// The Vulkan backend's first checks, under validation (any message fails the test): a device
// that does not exist is refused with the list of devices, clears store the soft backend's
// bits in every format, a Flat triangle draws what the soft backend draws (also when pipelines
// are made before its pass ends), a buffer updated
// while a submission reads it is renamed, and a steady frame creates nothing and waits at most
// once for a fence.
#include <gtest/gtest.h>

#include <glm/glm.hpp>

#include "draws.hpp"
#include "engine/core/error.hpp"
#include "engine/render/soft/soft_backend.hpp"
#include "engine/render/standard_programs.hpp"
#include "engine/render/vertex.hpp"
#include "vk_validation.hpp"

namespace {

using namespace engine::render;
using ssam::testing::meshDraw;
using ssam::testing::validatedVulkanBackend;
using ssam::testing::validatedVulkanOptions;

std::vector<Vertex> triangle() {
    Vertex a, b, c;
    a.position = {-0.8f, -0.7f, 0.5f};
    b.position = {0.9f, -0.6f, 0.5f};
    c.position = {0.1f, 0.85f, 0.5f};
    a.color = {1.0f, 0.2f, 0.1f, 1.0f};
    b.color = {0.1f, 1.0f, 0.3f, 0.5f};
    c.color = {0.2f, 0.3f, 1.0f, 1.0f};
    return {a, b, c};
}

// A triangle frame's 32x24 RGBA8 target and vertex buffer.
struct TriangleFrame {
    TextureHandle target;
    BufferHandle vb;
};
TriangleFrame triangleFrame(Backend& gfx, const std::vector<Vertex>& vertices) {
    return {gfx.createTexture(renderTargetDesc("target", 32, 24, Format::RGBA8_UNORM)),
            gfx.createBuffer({"triangle", BufferKind::Vertex, vertices.size() * sizeof(Vertex)},
                             std::as_bytes(std::span<const Vertex>(vertices)))};
}

// A 32x24 RGBA8 frame: clear, one Flat triangle with colour interpolation, read back.
Readback drawTriangle(Backend& gfx, const std::vector<Vertex>& vertices) {
    const auto [target, vb] = triangleFrame(gfx, vertices);
    PipelineDesc pd;
    pd.name = "flat";
    pd.program = ProgramKind::Flat;
    const PipelineHandle pipeline = gfx.createPipeline(pd);
    PassDesc pass;
    pass.name = "triangle";
    pass.color[0] = {target, LoadOp::Clear, glm::vec4(0.1f, 0.2f, 0.3f, 1.0f)};
    gfx.beginPass(pass);
    gfx.draw(meshDraw(pipeline, FlatParams{glm::mat4(1.0f), glm::vec4(1.0f, 0.9f, 0.8f, 1.0f)}, vb, 3));
    gfx.endPass();
    return gfx.readback(target);
}

TEST(VkBackend, MissingDeviceListsTheDevices) {
    vk::VulkanOptions options = validatedVulkanOptions();
    options.device = 99;
    try {
        vk::createVulkanBackend(options);
        FAIL() << "device 99 accepted";
    } catch (const engine::Error& e) {
        EXPECT_NE(std::string(e.what()).find("no device 99; devices: 0: "), std::string::npos) << e.what();
    }
}

TEST(VkBackend, ClearsStoreTheSoftBackendsBits) {
    auto gfx = validatedVulkanBackend();
    auto soft = soft::createSoftBackend();
    const glm::vec4 clear(0.3f, 0.61f, 0.5f + 1.0f / 512.0f, 0.2f);  // one channel on a rounding tie
    for (Format format : {Format::RGBA8_UNORM, Format::RGBA8_SRGB, Format::R8_UNORM, Format::RG8_UNORM, Format::RGBA16F,
                          Format::RG16F, Format::R16F, Format::RGBA32F, Format::R32F}) {
        SCOPED_TRACE(std::string(formatName(format)));
        Readback got, want;
        for (Backend* b : {static_cast<Backend*>(gfx.get()), static_cast<Backend*>(soft.get())}) {
            const TextureHandle t = b->createTexture(renderTargetDesc("t", 5, 3, format));
            PassDesc pass;
            pass.name = "clear";
            pass.color[0] = {t, LoadOp::Clear, clear};
            b->beginPass(pass);
            b->endPass();
            (b == gfx.get() ? got : want) = b->readback(t);
        }
        EXPECT_EQ(got.values, want.values);
    }
    EXPECT_EQ(engine::render::vk::vulkanDriver(*gfx).validationMessages(), 0u);
}

TEST(VkBackend, FlatTriangleMatchesTheSoftBackend) {
    auto gfx = validatedVulkanBackend();
    auto soft = soft::createSoftBackend();
    const Readback got = drawTriangle(*gfx, triangle()), want = drawTriangle(*soft, triangle());
    ASSERT_EQ(got.values.size(), want.values.size());
    int differ = 0, covered = 0;
    for (std::size_t i = 0; i < got.values.size(); ++i) {
        if (std::abs(got.values[i] - want.values[i]) > 1.5f / 255.0f) ++differ;
        if (want.values[i] != got.values[0]) ++covered;
    }
    EXPECT_GT(covered, 100);  // the triangle is there
    EXPECT_EQ(differ, 0);     // and within one code of the soft backend's everywhere
    EXPECT_EQ(engine::render::vk::vulkanDriver(*gfx).validationMessages(), 0u);
}

// Draws are recorded until endPass (on the soft backend too): pipelines created after a draw in
// the same pass (the pipeline pool grows and moves its slots) must not change what the draw
// records. Its pipeline culls the triangle (clockwise front faces, back faces culled): a draw
// that lost its pipeline's state draws it, or reads freed memory (ASan reports it). Found by the
// differential test, which creates pipelines mid-pass.
TEST(VkBackend, PipelinesCreatedMidPassLeaveRecordedDrawsIntact) {
    auto gfx = validatedVulkanBackend();
    auto soft = soft::createSoftBackend();
    const std::vector<Vertex> vertices = triangle();
    const glm::vec4 clear(0.1f, 0.2f, 0.3f, 1.0f);
    auto run = [&](Backend& b) {
        const auto [target, vb] = triangleFrame(b, vertices);
        PipelineDesc pd;
        pd.name = "culls the triangle";
        pd.program = ProgramKind::Flat;
        pd.raster.cull = CullMode::Back;
        pd.raster.frontFace = Winding::Clockwise;
        const PipelineHandle pipeline = b.createPipeline(pd);
        PassDesc pass;
        pass.name = "triangle";
        pass.color[0] = {target, LoadOp::Clear, clear};
        b.beginPass(pass);
        b.draw(meshDraw(pipeline, FlatParams{glm::mat4(1.0f), glm::vec4(1.0f, 0.9f, 0.8f, 1.0f)}, vb, 3));
        std::vector<PipelineHandle> more;
        for (int i = 0; i < 64; ++i) {
            pd.name = "made mid-pass " + std::to_string(i);
            more.push_back(b.createPipeline(pd));
        }
        b.endPass();
        b.destroy(pipeline);
        for (PipelineHandle h : more) b.destroy(h);
        b.destroy(vb);
        const Readback r = b.readback(target);
        b.destroy(target);
        return r;
    };
    const Readback got = run(*gfx), want = run(*soft);
    EXPECT_EQ(got.values, want.values);
    for (int y = 0; y < 24; ++y)
        for (int x = 0; x < 32; ++x) ASSERT_EQ(got.at(x, y, 0), want.at(0, 0, 0)) << "drawn at " << x << "," << y;
    EXPECT_EQ(engine::render::vk::vulkanDriver(*gfx).validationMessages(), 0u);
}

TEST(VkBackend, BufferUpdatedInFlightIsRenamed) {
    auto gfx = validatedVulkanBackend();
    std::vector<Vertex> vertices = triangle();
    const TextureHandle target = gfx->createTexture(renderTargetDesc("target", 16, 16, Format::RGBA8_UNORM));
    const BufferHandle vb = gfx->createBuffer({"tri", BufferKind::Vertex, 3 * sizeof(Vertex)},
                                              std::as_bytes(std::span<const Vertex>(vertices)));
    PipelineDesc pd;
    pd.program = ProgramKind::Flat;
    const PipelineHandle pipeline = gfx->createPipeline(pd);
    PassDesc pass;
    pass.name = "renamed";
    pass.color[0] = {target, LoadOp::Clear, glm::vec4(0.0f)};
    gfx->beginPass(pass);
    gfx->draw(meshDraw(pipeline, FlatParams{}, vb, 3));
    // Moved off screen after the draw was recorded: the draw keeps what it was given.
    for (Vertex& v : vertices) v.position.x += 10.0f;
    const std::uint64_t before = engine::render::vk::vulkanDriver(*gfx).counters().buffersCreated;
    gfx->updateBuffer(vb, 0, std::as_bytes(std::span<const Vertex>(vertices)));
    EXPECT_EQ(engine::render::vk::vulkanDriver(*gfx).counters().buffersCreated, before + 1);
    gfx->endPass();
    const Readback r = gfx->readback(target);
    EXPECT_GT(r.at(8, 8, 3), 0.4f);  // drawn where the triangle was (the clear is 0)
    EXPECT_EQ(engine::render::vk::vulkanDriver(*gfx).validationMessages(), 0u);
}

TEST(VkBackend, SteadyFrameCreatesNothingAndWaitsAtMostOnce) {
    auto gfx = validatedVulkanBackend();
    const std::vector<Vertex> vertices = triangle();
    const TextureHandle target = gfx->createTexture(renderTargetDesc("target", 16, 16, Format::RGBA8_UNORM));
    const TextureHandle depth = gfx->createTexture(renderTargetDesc("depth", 16, 16, Format::D32F));
    const BufferHandle vb = gfx->createBuffer({"tri", BufferKind::Vertex, 3 * sizeof(Vertex)},
                                              std::as_bytes(std::span<const Vertex>(vertices)));
    PipelineDesc pd;
    pd.program = ProgramKind::Flat;
    pd.depth.test = pd.depth.write = true;
    const PipelineHandle pipeline = gfx->createPipeline(pd);
    auto frame = [&] {
        PassDesc pass;
        pass.name = "frame";
        pass.color[0] = {target, LoadOp::Clear, glm::vec4(0.0f)};
        pass.depth = {depth, LoadOp::Clear, 1.0f};
        gfx->beginPass(pass);
        for (int i = 0; i < 50; ++i) gfx->draw(meshDraw(pipeline, FlatParams{}, vb, 3));
        gfx->endPass();
        gfx->updateBuffer(vb, 0, std::as_bytes(std::span<const Vertex>(vertices)));
        gfx->endFrame();
    };
    for (int i = 0; i < 4; ++i) frame();  // warm-up: pipelines, arena chunks, renamed buffers
    const vk::VulkanCounters warm = engine::render::vk::vulkanDriver(*gfx).counters();
    for (int i = 0; i < 6; ++i) frame();
    const vk::VulkanCounters& now = engine::render::vk::vulkanDriver(*gfx).counters();
    EXPECT_EQ(now.pipelinesCreated, warm.pipelinesCreated);
    EXPECT_EQ(now.imagesCreated, warm.imagesCreated);
    EXPECT_EQ(now.descriptorPoolsCreated, warm.descriptorPoolsCreated);
    // The per-frame vertex update renames the buffer while a frame reads it, from the spares.
    EXPECT_EQ(now.buffersCreated, warm.buffersCreated);
    EXPECT_LE(now.fenceWaits - warm.fenceWaits, 6u);  // at most one per frame
    EXPECT_EQ(now.resultWaits, warm.resultWaits);
    EXPECT_EQ(engine::render::vk::vulkanDriver(*gfx).validationMessages(), 0u);
}

}  // namespace
