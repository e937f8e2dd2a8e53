// SPDX-License-Identifier: MIT
// The pools that let a steady frame create nothing: FrameBufferPool (per-frame buffers) and
// TransientTexturePool (the frame graph's transient targets), on the soft backend, counted
// through a decorator.
#include <gtest/gtest.h>

#include <cstddef>
#include <vector>

#include "engine/render/frame_buffer_pool.hpp"
#include "engine/render/frame_graph.hpp"
#include "engine/render/frame_graph/backend_textures.hpp"
#include "engine/render/frame_graph/transient_texture_pool.hpp"
#include "engine/render/soft/soft_backend.hpp"
#include "failing_backend.hpp"

namespace {

using namespace engine::render;

std::vector<std::byte> bytesOfInstances(std::size_t count) { return std::vector<std::byte>(count * sizeof(Instance)); }

struct Pools : ::testing::Test {
    std::unique_ptr<Backend> soft = soft::createSoftBackend({.threads = 1, .tileSize = 64});
    ssam::testing::FailingBackend backend{*soft};  // never fails: counts creates and live resources
};

TEST_F(Pools, BufferPoolReusesAcrossFramesAndGrowsInPowersOfTwo) {
    FrameBufferPool pool(backend);
    pool.beginFrame();
    const BufferHandle a = pool.upload("instances", BufferKind::Instance, bytesOfInstances(3));
    const BufferHandle b = pool.upload("instances", BufferKind::Instance, bytesOfInstances(20));
    EXPECT_NE(a, b);  // both in use in one frame
    EXPECT_EQ(backend.creates, 2);
    // Capacities: whole elements, rounded up to a power of two (3 -> 4, 20 -> 32).
    backend.updateBuffer(a, 0, bytesOfInstances(4));
    EXPECT_THROW(backend.updateBuffer(a, 0, bytesOfInstances(5)), engine::Error);
    backend.updateBuffer(b, 0, bytesOfInstances(32));
    EXPECT_THROW(backend.updateBuffer(b, 0, bytesOfInstances(33)), engine::Error);

    pool.beginFrame();  // the same needs, in the other order: best fit, nothing created
    EXPECT_EQ(pool.upload("instances", BufferKind::Instance, bytesOfInstances(20)), b);
    EXPECT_EQ(pool.upload("instances", BufferKind::Instance, bytesOfInstances(3)), a);
    EXPECT_EQ(backend.creates, 2);

    pool.beginFrame();  // another name or kind never shares a buffer
    pool.upload("particles", BufferKind::Instance, bytesOfInstances(3));
    pool.upload("instances", BufferKind::Vertex, std::vector<std::byte>(sizeof(Vertex)));
    EXPECT_EQ(backend.creates, 4);
}

TEST_F(Pools, BufferPoolReusesALargerBufferForLessData) {
    FrameBufferPool pool(backend);
    pool.beginFrame();
    std::vector<std::uint32_t> indices{0, 1, 2, 7};
    const BufferHandle h = pool.upload("indices", BufferKind::Index, std::as_bytes(std::span(indices)));
    pool.beginFrame();
    indices = {5, 4, 3};
    EXPECT_EQ(pool.upload("indices", BufferKind::Index, std::as_bytes(std::span(indices))), h);
    EXPECT_EQ(backend.creates, 1);
}

TEST_F(Pools, BufferPoolRetiresWhatGoesUnused) {
    FrameBufferPool pool(backend);
    pool.beginFrame();
    pool.upload("instances", BufferKind::Instance, bytesOfInstances(1));
    EXPECT_EQ(backend.live, 1);
    for (std::uint64_t i = 0; i < FrameBufferPool::kRetireAfterFrames; ++i) pool.beginFrame();
    EXPECT_EQ(backend.live, 1);  // unused for exactly the limit: kept
    pool.beginFrame();
    EXPECT_EQ(backend.live, 0);
    EXPECT_EQ(pool.buffersHeld(), 0u);
}

// One frame: a transient written by one pass and read by a side-effect pass.
void runFrame(TransientTexturePool& pool, std::uint32_t width) {
    FrameGraph graph;
    struct Data {
        FrameGraphTexture t;
    };
    const Data& w = graph.addPass<Data>(
        "write",
        [&](FrameGraph::Builder& b, Data& d) {
            d.t = b.write(b.create("t", {width, 8, std::uint32_t(Format::RGBA8_UNORM), 1}));
        },
        [](const FrameGraph::Resources&, const Data&) {});
    graph.addPass<Data>(
        "present",
        [&](FrameGraph::Builder& b, Data&) {
            b.read(w.t);
            b.sideEffect();
        },
        [](const FrameGraph::Resources&, const Data&) {});
    graph.execute(pool.allocator());
    pool.endFrame();
}

TEST_F(Pools, TransientTexturesAreCreatedOnceForSteadyFrames) {
    TransientTexturePool pool(backend);
    runFrame(pool, 8);
    EXPECT_EQ(backend.creates, 1);
    for (int i = 0; i < 100; ++i) runFrame(pool, 8);
    EXPECT_EQ(backend.creates, 1);
    runFrame(pool, 16);  // another descriptor: another texture
    EXPECT_EQ(backend.creates, 2);
    EXPECT_EQ(pool.texturesHeld(), 2u);
    for (std::uint64_t i = 0; i <= TransientTexturePool::kRetireAfterFrames; ++i) runFrame(pool, 16);
    EXPECT_EQ(pool.texturesHeld(), 1u);  // the 8-wide one went unused and was destroyed
    EXPECT_EQ(backend.live, 1);
}

}  // namespace
