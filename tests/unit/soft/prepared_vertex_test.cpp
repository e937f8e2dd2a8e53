// SPDX-License-Identifier: MIT
// Set-up from prepared vertices (prepareVertex + setupPreparedTriangle: the vertex stage works
// out each vertex an indexed draw's triangles share once per instance) against setupTriangle on
// the same three vertices, bit for bit: the triangles appended (box, edges, facing, every plane)
// and the dropped count, for triangles made from a shared pool of vertices inside the view,
// beyond its sides, across the near and far planes, at w <= 0, huge, and non-finite, under each
// culling mode; a vertex's attributes are asked for once at most however many triangles use it.
#include <cmath>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "lcg.hpp"  // tests/support
#include "engine/render/kernel/detail/same_bits.hpp"
#include "engine/render/kernel/detail/triangle_setup.hpp"
#include "tile_rasterizer.hpp"

namespace {

using namespace engine::render;
using namespace engine::render::soft;

using ssam::testing::Lcg;

bool sameTriangle(const SetupTriangle& a, const SetupTriangle& b) {
    return a.drawIndex == b.drawIndex && a.frontFacing == b.frontFacing && a.minX == b.minX && a.minY == b.minY &&
           a.maxX == b.maxX && a.maxY == b.maxY && a.a == b.a && a.b == b.b && a.c == b.c &&
           sameBits(a.originX, b.originX) && sameBits(a.originY, b.originY) && sameBits(a.depth, b.depth) &&
           sameBits(a.inverseW, b.inverseW) && sameBits(a.attributeOverW, b.attributeOverW);
}

// A clip-space position: mostly in view, some beyond a side, across the near or far plane, at or
// behind w = 0, far beyond the guard band, or not finite.
glm::vec4 position(Lcg& rng) {
    auto u = [&](float lo, float hi) { return lo + (hi - lo) * rng.unit(); };
    const float w = u(0.5f, 20.0f);
    switch (rng.next() % 16) {
        case 0: return {u(-3.0f, 3.0f) * w, u(-3.0f, 3.0f) * w, u(0.0f, 1.0f) * w, w};   // beyond a side
        case 1: return {u(-1.0f, 1.0f) * w, u(-1.0f, 1.0f) * w, u(-0.5f, 0.0f) * w, w};  // behind z = 0
        case 2: return {u(-1.0f, 1.0f) * w, u(-1.0f, 1.0f) * w, u(1.0f, 1.5f) * w, w};   // beyond z = w
        case 3: return {u(-1.0f, 1.0f), u(-1.0f, 1.0f), u(0.0f, 1.0f), rng.next() % 2 ? 0.0f : -u(0.1f, 2.0f)};
        case 4: return {u(-1.0f, 1.0f) * 1.0e7f, u(-1.0f, 1.0f) * 1.0e7f, 0.5f, 1.0f};  // past the guard band
        case 5: return {std::numeric_limits<float>::quiet_NaN(), 0.0f, 0.5f, 1.0f};
        default: {  // in view, often small triangles near one another
            const float cx = std::floor(u(-1.0f, 1.0f) * 8.0f) / 8.0f, cy = std::floor(u(-1.0f, 1.0f) * 8.0f) / 8.0f;
            return {(cx + u(-0.05f, 0.05f)) * w, (cy + u(-0.05f, 0.05f)) * w, u(0.0f, 1.0f) * w, w};
        }
    }
}

// Attributes of pool vertex i, counted each time they are asked for.
class PoolAttributes final : public AttributeSource {
public:
    PoolAttributes(const std::vector<ClipVertex>& pool, const std::uint32_t (&index)[3], std::vector<int>& asked)
        : pool_(pool), index_(index), asked_(asked) {}
    void fillVertex(int k, ClipVertex& v) const override {
        v.attributes = pool_[index_[k]].attributes;
        ++asked_[index_[k]];
    }

private:
    const std::vector<ClipVertex>& pool_;
    const std::uint32_t (&index_)[3];
    std::vector<int>& asked_;
};

TEST(PreparedVertices, SetUpAsSetupTriangleDoes) {
    Lcg rng{31};
    const SamplePattern& pattern = samplePattern(1);
    int mismatches = 0;
    for (int round = 0; round < 200; ++round) {
        const Viewport vp{160 + int(rng.next() % 1200), 90 + int(rng.next() % 700), {}, &pattern};
        Viewport viewport = vp;
        viewport.scissor = {0, 0, vp.width, vp.height};
        RasterState raster;
        raster.cull = CullMode(rng.next() % 3);
        raster.frontFace = rng.next() % 2 ? Winding::CounterClockwise : Winding::Clockwise;
        std::vector<ClipVertex> pool(24);
        for (ClipVertex& v : pool) {
            v.position = position(rng);
            for (float& a : v.attributes) a = rng.unit() * 4.0f - 2.0f;
        }
        std::vector<PreparedVertex> prepared(pool.size());
        for (std::size_t i = 0; i < pool.size(); ++i) {
            prepared[i].clip.position = pool[i].position;
            prepareVertex(prepared[i], viewport);
        }
        std::vector<int> asked(pool.size(), 0);
        for (int t = 0; t < 200; ++t) {
            const std::uint32_t index[3] = {rng.next() % 24, rng.next() % 24, rng.next() % 24};
            std::vector<SetupTriangle> want, got;
            SetupCounters wantCounters, gotCounters;
            setupTriangle(pool[index[0]], pool[index[1]], pool[index[2]], viewport, raster, 7, want, wantCounters);
            PreparedVertex* const p[3] = {&prepared[index[0]], &prepared[index[1]], &prepared[index[2]]};
            // The vertex stage's reject (rejectedBeforeSetup) from the prepared vertices.
            if (!(p[0]->finite && p[1]->finite && p[2]->finite) ||
                outsideOnePlane(p[0]->clip, p[1]->clip, p[2]->clip, viewport)) {
                ++gotCounters.dropped;
            } else {
                setupPreparedTriangle(p, PoolAttributes(pool, index, asked), viewport, raster, 7, got, gotCounters);
            }
            bool same = want.size() == got.size() && wantCounters.dropped == gotCounters.dropped;
            for (std::size_t i = 0; same && i < want.size(); ++i) same = sameTriangle(want[i], got[i]);
            if (!same && ++mismatches <= 5)
                ADD_FAILURE() << "round " << round << " triangle " << index[0] << ", " << index[1] << ", " << index[2]
                              << ": setupTriangle made " << want.size() << " (dropped " << wantCounters.dropped
                              << "), prepared " << got.size() << " (dropped " << gotCounters.dropped << ")";
        }
    }
    EXPECT_EQ(mismatches, 0);
}

// With every vertex in view (no triangle clipped), a vertex's attributes are asked for once at
// most, however many kept triangles use it, and only if one is kept.
TEST(PreparedVertices, AttributesAskedOncePerVertex) {
    Lcg rng{32};
    const SamplePattern& pattern = samplePattern(1);
    const Viewport viewport{320, 180, {0, 0, 320, 180}, &pattern};
    std::vector<ClipVertex> pool(16);
    std::vector<PreparedVertex> prepared(pool.size());
    for (std::size_t i = 0; i < pool.size(); ++i) {
        pool[i].position = {rng.unit() * 1.6f - 0.8f, rng.unit() * 1.6f - 0.8f, rng.unit(), 1.0f};
        prepared[i].clip.position = pool[i].position;
        prepareVertex(prepared[i], viewport);
        ASSERT_TRUE(prepared[i].inside);
    }
    std::vector<int> asked(pool.size(), 0);
    std::vector<bool> used(pool.size(), false);
    std::vector<SetupTriangle> out;
    SetupCounters counters;
    for (int t = 0; t < 400; ++t) {
        const std::uint32_t index[3] = {rng.next() % 16, rng.next() % 16, rng.next() % 16};
        const std::size_t before = out.size();
        PreparedVertex* const p[3] = {&prepared[index[0]], &prepared[index[1]], &prepared[index[2]]};
        setupPreparedTriangle(p, PoolAttributes(pool, index, asked), viewport, RasterState{}, 0, out, counters);
        if (out.size() > before)
            for (std::uint32_t i : index) used[i] = true;
    }
    for (std::size_t i = 0; i < pool.size(); ++i) {
        EXPECT_LE(asked[i], 1) << "vertex " << i;
        EXPECT_EQ(asked[i] == 1, bool(used[i])) << "vertex " << i;
    }
}

}  // namespace
