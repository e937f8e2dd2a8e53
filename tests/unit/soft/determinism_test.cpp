// SPDX-License-Identifier: MIT
// Determinism: the same scene rendered with any thread count and tile size gives
// byte-identical images (soft_backend.hpp: primitives stay in submission order inside each
// tile). The scene is a few hundred random overlapping triangles with order-dependent state
// (alpha blending, additive float blending, depth test with writes, MSAA), plus one draw large
// enough to be split across the geometry stage's parallel chunks.
#include <cmath>
#include <cstring>
#include <random>

#include "soft_test_util.hpp"

namespace ssam::test::soft {
namespace {

struct Images {
    std::vector<render::Readback> images;
};

struct Scene {
    std::vector<render::Vertex> triangles;  // random, overlapping
    std::vector<render::Vertex> many;       // small ones, more than a geometry chunk
};

Scene makeScene(int count) {
    std::mt19937 rng(2024);
    auto next = [&] { return double(rng() >> 5) / double(1u << 27); };
    Scene s;
    for (int i = 0; i < count * 3; ++i) {
        render::Vertex v;
        v.position = {float(next() * 2.4 - 1.2), float(next() * 2.4 - 1.2), float(next())};
        v.color = {float(next()), float(next()), float(next()), float(next() * 0.8 + 0.1)};
        s.triangles.push_back(v);
    }
    for (int i = 0; i < 5000; ++i) {
        const float x = float(next() * 2 - 1), y = float(next() * 2 - 1), z = float(next());
        const glm::vec4 c{float(next()), float(next()), float(next()), 0.5f};
        for (auto [dx, dy] : {std::pair{0.0f, 0.0f}, {0.05f, 0.01f}, {0.02f, 0.06f}}) {
            render::Vertex v;
            v.position = {x + dx, y + dy, z};
            v.color = c;
            s.many.push_back(v);
        }
    }
    return s;
}

Images render(const SoftOptions& options, const Scene& scene, int samples) {
    auto gfx = createSoftBackend(options);
    constexpr int kWide = 150, kHigh = 97;  // not multiples of any tile size
    const render::TextureHandle color = makeTarget(*gfx, kWide, kHigh, Format::RGBA8_UNORM, samples, "color");
    const render::TextureHandle accum = makeTarget(*gfx, kWide, kHigh, Format::RGBA16F, samples, "accum");
    const render::TextureHandle depth = makeTarget(*gfx, kWide, kHigh, Format::D32F, samples, "depth");
    render::PipelineDesc desc = pipelineDesc("scene");
    desc.blend[0] = BlendState::alphaOver();
    desc.blend[1].enabled = true;
    desc.blend[1].srcRgb = desc.blend[1].srcAlpha = BlendFactor::SrcAlpha;
    desc.blend[1].dstRgb = desc.blend[1].dstAlpha = BlendFactor::One;
    desc.depth = render::DepthState::testAndWrite(render::CompareFunc::LessEqual);
    const render::PipelineHandle blended = gfx->createPipeline(desc);
    desc.depth = render::DepthState::testOnly(render::CompareFunc::Less);
    const render::PipelineHandle testOnly = gfx->createPipeline(desc);
    const render::BufferHandle tris = makeVertices(*gfx, scene.triangles);
    const render::BufferHandle many = makeVertices(*gfx, scene.many);

    render::PassDesc pass;
    pass.name = "scene";
    pass.color[0] = {color, render::LoadOp::Clear, {0.1f, 0.2f, 0.3f, 1.0f}};
    pass.color[1] = {accum, render::LoadOp::Clear, glm::vec4(0.0f)};
    pass.depth = {depth, render::LoadOp::Clear, 1.0f};
    gfx->beginPass(pass);
    const auto half = std::uint32_t(scene.triangles.size() / 6 * 3);
    render::DrawDesc d = flatDraw(blended, tris, half);
    gfx->draw(d);
    gfx->draw(flatDraw(testOnly, many, std::uint32_t(scene.many.size()), {1.0f, 0.5f, 0.25f, 1.0f}));
    d.first = half;
    d.count = std::uint32_t(scene.triangles.size()) - half;
    gfx->draw(d);
    gfx->endPass();

    Images out;
    for (render::TextureHandle t : {color, accum, depth}) {
        if (samples == 1) {
            out.images.push_back(gfx->readback(t));
        } else {
            const render::TextureDesc& td = gfx->describe(t);
            const render::TextureHandle single = makeTarget(*gfx, td.width, td.height, td.format, 1, "resolved");
            gfx->resolve({t, single});
            out.images.push_back(gfx->readback(single));
        }
    }
    return out;
}

void expectIdentical(const Images& a, const Images& b, const std::string& what) {
    ASSERT_EQ(a.images.size(), b.images.size());
    for (std::size_t i = 0; i < a.images.size(); ++i) {
        const auto& va = a.images[i].values;
        const auto& vb = b.images[i].values;
        ASSERT_EQ(va.size(), vb.size());
        EXPECT_EQ(std::memcmp(va.data(), vb.data(), va.size() * sizeof(float)), 0)
            << what << ": image " << i << " differs";
    }
}

const SoftOptions kVariants[] = {
    {.threads = 2, .tileSize = 64}, {.threads = 2, .tileSize = 8},    {.threads = 1, .tileSize = 16},
    {.threads = 0, .tileSize = 24}, {.threads = 2, .tileSize = 1024}, {.threads = 2, .tileSize = 32},
};

TEST(SoftDeterminism, SameImagesForAnyThreadCountAndTileSize) {
    const Scene scene = makeScene(400);
    const Images reference = render({.threads = 1, .tileSize = 64}, scene, 1);
    // The scene covers most of the target.
    const render::Readback& c = reference.images[0];
    int drawn = 0;
    for (int y = 0; y < c.height; ++y)
        for (int x = 0; x < c.width; ++x) drawn += std::lround(c.at(x, y, 2) * 255.0f) != std::lround(0.3f * 255.0f);
    EXPECT_GT(drawn, c.width * c.height / 2);
    for (const SoftOptions& o : kVariants)
        expectIdentical(reference, render(o, scene, 1),
                        "threads " + std::to_string(o.threads) + " tile " + std::to_string(o.tileSize));
}

TEST(SoftDeterminism, SameImagesMultisampled) {
    const Scene scene = makeScene(300);
    const Images reference = render({.threads = 1, .tileSize = 64}, scene, 4);
    for (const SoftOptions& o : {SoftOptions{.threads = 2, .tileSize = 64}, SoftOptions{.threads = 2, .tileSize = 8}})
        expectIdentical(reference, render(o, scene, 4),
                        "4x threads " + std::to_string(o.threads) + " tile " + std::to_string(o.tileSize));
}

}  // namespace
}  // namespace ssam::test::soft
