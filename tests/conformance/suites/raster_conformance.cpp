// SPDX-License-Identifier: MIT
// Rasterizer conventions every backend shares: NDC +y is the top row, counter-clockwise as
// displayed is front-facing by default, culling, scissor, instancing (transform and tint),
// vertex colour interpolation and multiple render targets with their own blend state.
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "../backend_fixture.hpp"

namespace ssam::test {
namespace {

using render::CullMode;
using render::Winding;

constexpr int kSize = 8;

render::Vertex at(float x, float y, glm::vec4 color = glm::vec4(1.0f)) {
    render::Vertex v;
    v.position = {x, y, 0.5f};
    v.color = color;
    return v;
}

TEST_P(RasterConformance, PositiveNdcYIsTheTopRow) {
    const render::TextureHandle target = renderTarget(kSize, kSize, Format::RGBA8_UNORM);
    const render::BufferHandle top = vertexBuffer({at(-1, 0), at(1, 0), at(1, 1), at(-1, 0), at(1, 1), at(-1, 1)});
    const render::PipelineHandle pipeline = flatPipeline();
    pass(target, glm::vec4(0.0f), [&] { drawFlat(pipeline, top, 6); });
    const render::Readback r = gfx().readback(target);
    for (int y = 0; y < kSize; ++y) EXPECT_EQ(r.at(3, y, 0), y < kSize / 2 ? 1.0f : 0.0f) << "row " << y;
}

// (-1,-1), (1,-1), (0,1) runs counter-clockwise as displayed (y up on screen).
TEST_P(RasterConformance, CullingAndFrontFace) {
    const render::TextureHandle target = renderTarget(kSize, kSize, Format::RGBA8_UNORM);
    const render::BufferHandle ccw = vertexBuffer({at(-1, -1), at(1, -1), at(0, 1)});
    const render::BufferHandle cw = vertexBuffer({at(-1, -1), at(0, 1), at(1, -1)});
    struct Case {
        CullMode cull;
        Winding front;
        bool ccwDrawn, cwDrawn;
    };
    const Case cases[] = {
        {CullMode::None, Winding::CounterClockwise, true, true},
        {CullMode::Back, Winding::CounterClockwise, true, false},
        {CullMode::Front, Winding::CounterClockwise, false, true},
        {CullMode::Back, Winding::Clockwise, false, true},
        {CullMode::Front, Winding::Clockwise, true, false},
    };
    for (const Case& k : cases) {
        render::PipelineDesc desc;
        desc.name = "cull";
        desc.raster = {k.cull, k.front};
        const render::PipelineHandle pipeline = gfx().createPipeline(desc);
        for (bool useCcw : {true, false}) {
            pass(target, glm::vec4(0.0f), [&] { drawFlat(pipeline, useCcw ? ccw : cw, 3); });
            EXPECT_EQ(gfx().readback(target).at(4, 5, 0), (useCcw ? k.ccwDrawn : k.cwDrawn) ? 1.0f : 0.0f)
                << "cull " << int(k.cull) << " front " << int(k.front) << (useCcw ? " ccw" : " cw");
        }
    }
}

TEST_P(RasterConformance, Scissor) {
    const render::TextureHandle target = renderTarget(kSize, kSize, Format::RGBA8_UNORM);
    const render::BufferHandle quad = vertexBuffer(pixelRect(kSize, kSize, 0, 0, kSize, kSize));
    const render::PipelineHandle pipeline = flatPipeline();
    const render::Rect rects[] = {{1, 2, 3, 2}, {-3, 5, 5, 10}, {6, 6, 0, 2}, {9, 0, 4, 4}};
    for (const render::Rect& rect : rects) {
        pass(target, glm::vec4(0.0f), [&] {
            auto d = meshDraw(pipeline, render::FlatParams{}, quad, 6);
            d.scissor = rect;
            gfx().draw(d);
        });
        const render::Readback r = gfx().readback(target);
        for (int y = 0; y < kSize; ++y)
            for (int x = 0; x < kSize; ++x) {
                const bool inside = x >= rect.x && x < rect.x + rect.width && y >= rect.y && y < rect.y + rect.height;
                EXPECT_EQ(r.at(x, y, 0), inside ? 1.0f : 0.0f)
                    << "scissor " << rect.x << "," << rect.y << " " << rect.width << "x" << rect.height << " pixel "
                    << x << "," << y;
            }
    }
}

// Flat: out = params.color * vertex.color * instance.tint, each instance moved by its model
// matrix.
TEST_P(RasterConformance, InstancesTransformAndTint) {
    const render::TextureHandle target = renderTarget(kSize, kSize, Format::RGBA32F);
    // A 2x2-pixel quad in the top-left corner, moved right by 2 pixels per instance.
    const render::BufferHandle quad = vertexBuffer(pixelRect(kSize, kSize, 0, 0, 2, 2, 0.5f, {0.5f, 1.0f, 1.0f, 1.0f}));
    std::vector<render::Instance> instances(3);
    for (int i = 0; i < 3; ++i) {
        instances[i].model = glm::translate(glm::mat4(1.0f), glm::vec3(2.0f * 2.0f * i / kSize, 0.0f, 0.0f));
        instances[i].tint = {1.0f, 0.25f * (i + 1), 1.0f, 1.0f};
    }
    const render::BufferHandle ib = gfx().createBuffer(
        {"instances", render::BufferKind::Instance, instances.size() * sizeof(render::Instance)}, bytesOf(instances));
    const render::PipelineHandle pipeline = flatPipeline();
    pass(target, glm::vec4(0.0f), [&] {
        auto d = meshDraw(pipeline, render::FlatParams{glm::mat4(1.0f), {1.0f, 1.0f, 0.5f, 1.0f}}, quad, 6);
        d.instances = ib;
        d.instanceCount = 3;
        gfx().draw(d);
    });
    const render::Readback r = gfx().readback(target);
    for (int i = 0; i < 3; ++i) {
        EXPECT_FLOAT_EQ(r.at(2 * i + 1, 1, 0), 0.5f) << i;
        EXPECT_FLOAT_EQ(r.at(2 * i + 1, 1, 1), 0.25f * (i + 1)) << i;
        EXPECT_FLOAT_EQ(r.at(2 * i + 1, 1, 2), 0.5f) << i;
    }
    EXPECT_EQ(r.at(7, 1, 3), 0.0f);
    EXPECT_EQ(r.at(1, 3, 3), 0.0f);
}

// Vertex colours interpolate linearly in screen space at w = 1: at pixel centre p the colour
// is the barycentric combination.
TEST_P(RasterConformance, VertexColourInterpolation) {
    constexpr int kWide = 16;
    const render::TextureHandle target = renderTarget(kWide, kWide, Format::RGBA32F);
    const glm::dvec2 p[3] = {{0.0, 16.0}, {16.0, 16.0}, {0.0, 0.0}};  // pixels
    std::vector<render::Vertex> tri;
    const glm::vec4 colors[3] = {{1, 0, 0, 1}, {0, 1, 0, 1}, {0, 0, 1, 1}};
    for (int i = 0; i < 3; ++i) {
        render::Vertex v = pixelVertex(kWide, kWide, p[i].x, p[i].y);
        v.color = colors[i];
        tri.push_back(v);
    }
    const render::BufferHandle vb = vertexBuffer(tri);
    const render::PipelineHandle pipeline = flatPipeline();
    pass(target, glm::vec4(0.0f), [&] { drawFlat(pipeline, vb, 3); });
    const render::Readback r = gfx().readback(target);
    int checked = 0;
    for (int y = 0; y < kWide; ++y)
        for (int x = 0; x < kWide; ++x) {
            const glm::dvec2 c(x + 0.5, y + 0.5);
            // Barycentrics of the right triangle: b1 along x, b2 along -y.
            const double b1 = c.x / 16.0, b2 = (16.0 - c.y) / 16.0, b0 = 1.0 - b1 - b2;
            if (b0 < 0.01) continue;
            ++checked;
            EXPECT_NEAR(r.at(x, y, 0), b0, 1e-5) << x << "," << y;
            EXPECT_NEAR(r.at(x, y, 1), b1, 1e-5) << x << "," << y;
            EXPECT_NEAR(r.at(x, y, 2), b2, 1e-5) << x << "," << y;
        }
    EXPECT_GT(checked, 100);
}

// A draw renders the buffers as they were when it was issued (GL semantics): updating a
// vertex, index or instance buffer later in the same pass changes only later draws.
TEST_P(RasterConformance, BufferUpdatesAfterADrawDoNotChangeIt) {
    const render::TextureHandle target = renderTarget(kSize, kSize, Format::RGBA32F);
    const std::vector<render::Vertex> left = pixelRect(kSize, kSize, 0, 0, kSize / 2, kSize);
    const std::vector<render::Vertex> right = pixelRect(kSize, kSize, kSize / 2, 0, kSize, kSize);
    const render::BufferHandle vb = vertexBuffer(left);
    const render::PipelineHandle pipeline = flatPipeline();
    pass(target, glm::vec4(0.0f), [&] {
        drawFlat(pipeline, vb, 6, {1, 0, 0, 1});
        gfx().updateBuffer(vb, 0, bytesOf(right));
        drawFlat(pipeline, vb, 6, {0, 1, 0, 1});
    });
    render::Readback r = gfx().readback(target);
    EXPECT_EQ(r.at(1, 3, 0), 1.0f) << "the first draw used the left half";
    EXPECT_EQ(r.at(1, 3, 1), 0.0f);
    EXPECT_EQ(r.at(6, 3, 1), 1.0f) << "the second draw used the right half";
    EXPECT_EQ(r.at(6, 3, 0), 0.0f);

    // Index and instance buffers too.
    std::vector<render::Vertex> both = left;
    both.insert(both.end(), right.begin(), right.end());
    const render::BufferHandle vb2 = vertexBuffer(both);
    const render::BufferHandle ib = indexBuffer({0, 1, 2, 3, 4, 5});
    std::vector<render::Instance> tint(1);
    tint[0].tint = {0, 0, 1, 1};
    const render::BufferHandle instances =
        gfx().createBuffer({"instances", render::BufferKind::Instance, sizeof(render::Instance)}, bytesOf(tint));
    pass(target, glm::vec4(0.0f), [&] {
        render::DrawDesc d;
        d.pipeline = pipeline;
        d.params = render::FlatParams{};
        d.vertices = vb2;
        d.indices = ib;
        d.count = 6;
        d.instances = instances;
        gfx().draw(d);
        gfx().updateBuffer(ib, 0, bytesOf(std::vector<std::uint32_t>{6, 7, 8, 9, 10, 11}));
        tint[0].tint = {1, 1, 0, 1};
        gfx().updateBuffer(instances, 0, bytesOf(tint));
        gfx().draw(d);
    });
    r = gfx().readback(target);
    EXPECT_EQ(r.at(1, 3, 2), 1.0f) << "first draw: left half, blue";
    EXPECT_EQ(r.at(1, 3, 0), 0.0f);
    EXPECT_EQ(r.at(6, 3, 0), 1.0f) << "second draw: right half, yellow";
    EXPECT_EQ(r.at(6, 3, 2), 0.0f);
}

// Every colour target gets the program's output, each through its own blend state.
TEST_P(RasterConformance, MultipleTargetsWithTheirOwnBlend) {
    const render::TextureHandle a = renderTarget(kSize, kSize, Format::RGBA32F, 1, "a");
    const render::TextureHandle b = renderTarget(kSize, kSize, Format::RGBA32F, 1, "b");
    const render::TextureHandle c = renderTarget(kSize, kSize, Format::RGBA8_UNORM, 1, "c");
    render::PipelineDesc desc;
    desc.name = "mrt";
    desc.blend[0] = BlendState::opaque();
    desc.blend[1].enabled = true;
    desc.blend[1].srcRgb = desc.blend[1].dstRgb = desc.blend[1].srcAlpha = desc.blend[1].dstAlpha = BlendFactor::One;
    desc.blend[2] = BlendState::alphaOver();
    const render::PipelineHandle pipeline = gfx().createPipeline(desc);
    const render::BufferHandle quad = vertexBuffer(pixelRect(kSize, kSize, 0, 0, kSize, kSize));
    render::PassDesc p;
    p.name = "mrt";
    p.color[0] = {a, render::LoadOp::Clear, {0.5f, 0.5f, 0.5f, 0.5f}};
    p.color[1] = {b, render::LoadOp::Clear, {0.5f, 0.5f, 0.5f, 0.5f}};
    p.color[2] = {c, render::LoadOp::Clear, {0.0f, 0.0f, 0.0f, 1.0f}};
    gfx().beginPass(p);
    drawFlat(pipeline, quad, 6, {1.0f, 0.25f, 0.0f, 0.5f});
    gfx().endPass();
    const render::Readback ra = gfx().readback(a), rb = gfx().readback(b), rc = gfx().readback(c);
    EXPECT_EQ(ra.at(2, 2, 0), 1.0f);
    EXPECT_EQ(ra.at(2, 2, 3), 0.5f);
    EXPECT_EQ(rb.at(2, 2, 0), 1.5f);
    EXPECT_EQ(rb.at(2, 2, 1), 0.75f);
    EXPECT_EQ(rb.at(2, 2, 3), 1.0f);
    EXPECT_NEAR(rc.at(2, 2, 0), 0.5f, 1.0f / 255.0f);
    EXPECT_NEAR(rc.at(2, 2, 1), 0.125f, 1.0f / 255.0f);
    EXPECT_NEAR(rc.at(2, 2, 3), 0.5f + 0.5f * 1.0f, 1.0f / 255.0f);  // alpha ONE / INV_SRC_ALPHA
}

}  // namespace
}  // namespace ssam::test
