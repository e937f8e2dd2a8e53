// SPDX-License-Identifier: MIT
// Depth test and write: the eight compare functions with writes on and off, the test off,
// reverse-Z, interpolation of a sloped depth, and exact repeatability across passes.
#include <array>
#include <cmath>

#include "../backend_fixture.hpp"

namespace ssam::test {
namespace {

constexpr int kSize = 8;

TEST_P(DepthConformance, EveryFuncWithWriteOnAndOff) {
    const auto [color, depth] = colorAndDepthTargets(kSize, kSize);
    const float stored = 0.5f;
    for (CompareFunc func : render::kAllCompareFuncs) {
        for (bool write : {false, true}) {
            const render::PipelineHandle pipeline = flatPipeline({}, {true, write, func});
            for (float z : {0.25f, 0.5f, 0.75f}) {
                const render::BufferHandle quad = vertexBuffer(pixelRect(kSize, kSize, 0, 0, kSize, kSize, z));
                pass(
                    color, {0, 0, 0, 0},
                    [&] {
                        drawFlat(pipeline, quad, 6, {1, 0, 0, 1});
                    },
                    depth, stored);
                const bool passes = referenceCompare(func, z, stored);
                const auto [c, d] = readBoth(color, depth);
                for (int y = 0; y < kSize; ++y)
                    for (int x = 0; x < kSize; ++x) {
                        ASSERT_EQ(c.at(x, y, 0), passes ? 1.0f : 0.0f)
                            << render::compareFuncName(func) << " write " << write << " z " << z;
                        ASSERT_EQ(d.at(x, y, 0), passes && write ? z : stored)
                            << render::compareFuncName(func) << " write " << write << " z " << z;
                    }
                gfx().destroy(quad);
            }
            gfx().destroy(pipeline);
        }
    }
}

// With the test off nothing is tested and nothing is written, whatever `write` says (GL:
// depth writes need GL_DEPTH_TEST enabled).
TEST_P(DepthConformance, TestOffNeitherTestsNorWrites) {
    const auto [color, depth] = colorAndDepthTargets(kSize, kSize);
    const render::PipelineHandle pipeline = flatPipeline({}, {false, true, CompareFunc::Never});
    const render::BufferHandle quad = vertexBuffer(pixelRect(kSize, kSize, 0, 0, kSize, kSize, 0.75f));
    pass(
        color, {0, 0, 0, 0}, [&] { drawFlat(pipeline, quad, 6); }, depth, 0.5f);
    EXPECT_EQ(gfx().readback(color).at(3, 3, 0), 1.0f);
    EXPECT_EQ(gfx().readback(depth).at(3, 3, 0), 0.5f);
}

// Reverse-Z: clear to 0, Greater; the nearest surface (largest depth) wins whatever the order.
TEST_P(DepthConformance, ReverseZ) {
    const auto [color, depth] = colorAndDepthTargets(kSize, kSize);
    const render::PipelineHandle pipeline = flatPipeline({}, DepthState::testAndWrite(CompareFunc::Greater));
    auto fullQuadAt = [&](float z) { return vertexBuffer(pixelRect(kSize, kSize, 0, 0, kSize, kSize, z)); };
    struct Surface {
        render::BufferHandle quad;
        glm::vec4 color;
    };
    const Surface nearest{fullQuadAt(0.8f), {1, 0, 0, 1}}, middle{fullQuadAt(0.5f), {0, 0, 1, 1}},
        farthest{fullQuadAt(0.2f), {0, 1, 0, 1}};
    // Near first (the others are hidden), then far first (each nearer one replaces it).
    for (const auto& order : {std::array{nearest, farthest, middle}, std::array{farthest, middle, nearest}}) {
        pass(
            color, {0, 0, 0, 0},
            [&] {
                for (const Surface& s : order) drawFlat(pipeline, s.quad, 6, s.color);
            },
            depth, 0.0f);
        const render::Readback c = gfx().readback(color);
        EXPECT_EQ(c.at(4, 4, 0), 1.0f);
        EXPECT_EQ(c.at(4, 4, 1), 0.0f);
        EXPECT_EQ(c.at(4, 4, 2), 0.0f);
        EXPECT_EQ(gfx().readback(depth).at(4, 4, 0), 0.8f);
    }
    // A surface at the cleared depth 0 (the far plane) fails Greater.
    const render::BufferHandle atFar = fullQuadAt(0.0f);
    pass(
        color, {0, 0, 0, 0}, [&] { drawFlat(pipeline, atFar, 6); }, depth, 0.0f);
    EXPECT_EQ(gfx().readback(color).at(4, 4, 0), 0.0f);
}

// A quad whose depth runs from 0 (left edge) to 1 (right edge) against a flat one at 0.5:
// depth at pixel centre x is (x + 0.5) / width, so exactly the left half is in front.
TEST_P(DepthConformance, SlopedDepthInterpolation) {
    const auto [color, depth] = colorAndDepthTargets(kSize, kSize);
    const render::PipelineHandle pipeline = flatPipeline({}, DepthState::testAndWrite(CompareFunc::Less));
    const render::BufferHandle flat = vertexBuffer(pixelRect(kSize, kSize, 0, 0, kSize, kSize, 0.5f));
    std::vector<render::Vertex> slope = pixelRect(kSize, kSize, 0, 0, kSize, kSize);
    for (render::Vertex& v : slope) v.position.z = (v.position.x + 1.0f) * 0.5f;
    const render::BufferHandle sloped = vertexBuffer(slope);
    pass(
        color, {0, 0, 0, 0},
        [&] {
            drawFlat(pipeline, flat, 6, {0, 1, 0, 1});
            drawFlat(pipeline, sloped, 6, {1, 0, 0, 1});
        },
        depth, 1.0f);
    const auto [c, d] = readBoth(color, depth);
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            const float expected = (float(x) + 0.5f) / kSize;
            const bool front = expected < 0.5f;
            EXPECT_EQ(c.at(x, y, 0), front ? 1.0f : 0.0f) << x << "," << y;
            EXPECT_NEAR(d.at(x, y, 0), front ? expected : 0.5f, 1e-6f) << x << "," << y;
        }
}

// The same geometry drawn again gives bit-identical depth (GL invariance rule), so an Equal
// pass over a depth pre-pass covers exactly the same pixels, and NotEqual none.
TEST_P(DepthConformance, RepeatedGeometryIsInvariant) {
    constexpr int kWide = 37, kHigh = 23;  // odd sizes: not multiples of any tile size
    const auto [color, depth] = colorAndDepthTargets(kWide, kHigh);
    std::vector<render::Vertex> tri = {pixelVertex(kWide, kHigh, 1.3, 2.7, 0.1f),
                                       pixelVertex(kWide, kHigh, 35.1, 5.2, 0.9f),
                                       pixelVertex(kWide, kHigh, 9.7, 21.9, 0.37f)};
    const render::BufferHandle vb = vertexBuffer(tri);
    const render::PipelineHandle prepass = flatPipeline({}, DepthState::testAndWrite(CompareFunc::Less));
    const render::PipelineHandle equal = flatPipeline({}, DepthState::testOnly(CompareFunc::Equal));
    const render::PipelineHandle notEqual = flatPipeline({}, DepthState::testOnly(CompareFunc::NotEqual));
    pass(
        color, {0, 0, 0, 0},
        [&] {
            drawFlat(prepass, vb, 3, {0, 0, 1, 1});
        },
        depth, 1.0f);
    const render::Readback first = gfx().readback(color);
    pass(
        color, {0, 0, 0, 0},
        [&] {
            drawFlat(equal, vb, 3, {1, 0, 0, 1});
            drawFlat(notEqual, vb, 3, {0, 1, 0, 1});
        },
        depth, std::nullopt);
    const render::Readback second = gfx().readback(color);
    int covered = 0;
    for (int y = 0; y < kHigh; ++y)
        for (int x = 0; x < kWide; ++x) {
            const bool wasCovered = first.at(x, y, 2) == 1.0f;
            covered += wasCovered;
            EXPECT_EQ(second.at(x, y, 0), wasCovered ? 1.0f : 0.0f) << x << "," << y;
            EXPECT_EQ(second.at(x, y, 1), 0.0f) << x << "," << y;
        }
    EXPECT_GT(covered, 100);
}

// Depth loaded (not cleared) carries over between passes.
TEST_P(DepthConformance, LoadKeepsDepthAcrossPasses) {
    const auto [color, depth] = colorAndDepthTargets(kSize, kSize);
    const render::PipelineHandle pipeline = flatPipeline({}, DepthState::testAndWrite(CompareFunc::Less));
    const render::BufferHandle left = vertexBuffer(pixelRect(kSize, kSize, 0, 0, kSize / 2, kSize, 0.3f));
    const render::BufferHandle full = vertexBuffer(pixelRect(kSize, kSize, 0, 0, kSize, kSize, 0.6f));
    pass(
        color, {0, 0, 0, 0}, [&] { drawFlat(pipeline, left, 6); }, depth, 1.0f);
    pass(
        color, {0, 0, 0, 0},
        [&] {
            drawFlat(pipeline, full, 6, {0, 1, 0, 1});
        },
        depth, std::nullopt);
    const auto [c, d] = readBoth(color, depth);
    for (int x = 0; x < kSize; ++x) {
        EXPECT_EQ(c.at(x, 3, 1), x < kSize / 2 ? 0.0f : 1.0f) << x;
        EXPECT_EQ(d.at(x, 3, 0), x < kSize / 2 ? 0.3f : 0.6f) << x;
    }
}

}  // namespace
}  // namespace ssam::test
