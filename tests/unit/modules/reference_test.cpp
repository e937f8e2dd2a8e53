// SPDX-License-Identifier: MIT
// The exact reference (modules/transparency reference_technique.cpp): every fragment, sorted
// per pixel, "over" front to back; ties in submission order; the cap reported.
#include <gtest/gtest.h>

#include "engine/core/error.hpp"
#include "technique_fixture.hpp"
#include "two_quads.hpp"

namespace {

using namespace transparency;
using namespace transparency::testing;

const Quad kQuadC{-0.5f, -1.0f, 0.5f, 1.0f, 0.45f, {0.0f, 0.0f, 1.0f, 0.5f}};  // blue, between A and B
const glm::vec3 kOpaque(kOpaqueColor);

struct ReferenceRun {
    std::unique_ptr<engine::render::Device> backend = soft::createSoftBackend({});
    std::unique_ptr<Technique> technique;
    Readback image;
    ReferenceRun(const std::vector<Quad>& foliage, TechniqueOptions options = {}, const std::vector<Quad>& walls = {}) {
        technique = createTechnique(TechniqueKind::Reference, *backend, options);
        TechniqueFrame f(*backend, 1, foliage);
        image = f.run(*technique, walls);
    }
    glm::vec3 at(int x, int y) const { return rgbAt(image, x, y); }
};

TEST(Reference, IsExactOverInEitherSubmissionOrder) {
    for (bool reversed : {false, true}) {
        ReferenceRun r(reversed ? std::vector<Quad>{kQuadB, kQuadA} : std::vector<Quad>{kQuadA, kQuadB});
        const std::string order = reversed ? "B first" : "A first";
        expectRgbNear(r.at(kOnlyA, kRow), over(kQuadA.color, kOpaque), 1e-6f, "only A, " + order);
        expectRgbNear(r.at(kOnlyB, kRow), over(kQuadB.color, kOpaque), 1e-6f, "only B, " + order);
        expectRgbNear(r.at(kOverlap, kRow), over(kQuadA.color, over(kQuadB.color, kOpaque)), 1e-6f,
                      "overlap, " + order);
        EXPECT_EQ(r.image.at(kOverlap, kRow, 3), 1.0f);
        const auto report = r.technique->referenceReport();
        ASSERT_TRUE(report);
        EXPECT_TRUE(report->exact());
        EXPECT_EQ(report->maxFragmentsPerPixel, 2u);
        // A covers 10 columns, B 10, the whole height: 20 * 16 fragments.
        EXPECT_EQ(report->fragments, 20u * kSize);
    }
}

// Coplanar quads: the earlier-submitted fragment is in front (stable sort).
TEST(Reference, CoplanarFragmentsKeepSubmissionOrder) {
    Quad first = kQuadA, second = kQuadB;
    second.depth = first.depth;
    ReferenceRun r({first, second});
    expectRgbNear(r.at(kOverlap, kRow), over(first.color, over(second.color, kOpaque)), 1e-6f, "first in front");
    ReferenceRun swapped({second, first});
    expectRgbNear(swapped.at(kOverlap, kRow), over(second.color, over(first.color, kOpaque)), 1e-6f,
                  "second submitted first is in front");
}

// Interpenetrating quads: a quad whose depth runs from 0.2 (left) to 0.8 (right) crosses a
// flat one at 0.5 in the middle; per pixel the nearer one is in front, which no per-object
// sort can get right on both sides.
TEST(Reference, SortsPerPixelThroughIntersections) {
    auto backend = soft::createSoftBackend({});
    auto reference = createTechnique(TechniqueKind::Reference, *backend, {});
    auto sorted = createTechnique(TechniqueKind::BlendSorted, *backend, {});
    const glm::vec4 red{1, 0, 0, 0.5f}, green{0, 1, 0, 0.7f};
    std::vector<Vertex> slanted(6);
    const glm::vec3 corners[6] = {{-1, -1, 0.2f}, {1, -1, 0.8f}, {1, 1, 0.8f},
                                  {-1, -1, 0.2f}, {1, 1, 0.8f},  {-1, 1, 0.2f}};
    for (int i = 0; i < 6; ++i) slanted[i].position = corners[i], slanted[i].color = red;
    const auto bytes = std::as_bytes(std::span(slanted));
    const BufferHandle buffer = backend->createBuffer({"slanted", BufferKind::Vertex, bytes.size()}, bytes);
    for (Technique* technique : {reference.get(), sorted.get()}) {
        TechniqueFrame f(*backend, 1, {{-1, -1, 1, 1, 0.5f, green}});
        FoliageDraw slantedDraw;
        slantedDraw.batch.vertices = buffer;
        slantedDraw.batch.count = 6;
        slantedDraw.batch.worldBounds = {{-1, -1, 0.2f}, {1, 1, 0.8f}};
        slantedDraw.meshBounds = slantedDraw.batch.worldBounds;
        f.draws.push_back(slantedDraw);
        const Readback r = f.run(*technique);
        const glm::vec3 redInFront = over(red, over(green, kOpaque)), greenInFront = over(green, over(red, kOpaque));
        if (technique == reference.get()) {
            expectRgbNear(rgbAt(r, 2, kRow), redInFront, 1e-6f, "left: red nearer");
            expectRgbNear(rgbAt(r, 13, kRow), greenInFront, 1e-6f, "right: green nearer");
        } else {  // both centres at 0.5: sorted keeps submission order, green drawn first
            expectRgbNear(rgbAt(r, 2, kRow), redInFront, 1e-6f, "sorted, left");
            EXPECT_GT(glm::length(rgbAt(r, 13, kRow) - greenInFront), 0.1f) << "sorted is wrong on the right";
        }
    }
    backend->destroy(buffer);
}

TEST(Reference, HonoursTheOpaqueDepth) {
    ReferenceRun r({kQuadA, kQuadB}, {}, {{0.0f, -1.0f, 1.0f, 1.0f, 0.5f, {1, 1, 1, 1}}});
    // Right half: an opaque white wall at 0.5, in front of B (0.6), behind A (0.3).
    expectRgbNear(r.at(kOnlyB, kRow), glm::vec3(1.0f), 1e-6f, "B hidden by the wall");
    expectRgbNear(r.at(9, kRow), over(kQuadA.color, glm::vec3(1.0f)), 1e-6f, "A over the wall");
}

TEST(Reference, ReportsPixelsOverTheCap) {
    TechniqueOptions options;
    options.referenceFragmentsPerPixel = 2;
    ReferenceRun r({kQuadB, kQuadA, kQuadC}, options);
    const auto report = r.technique->referenceReport();
    ASSERT_TRUE(report);
    EXPECT_FALSE(report->exact());
    // A, B and C overlap in columns 6..9 (C: columns 4..11), the whole height.
    EXPECT_EQ(report->pixelsOverCap, 4u * kSize);
    EXPECT_EQ(report->fragmentsOverCap, 4u * kSize);
    EXPECT_EQ(report->maxFragmentsPerPixel, 3u);
    // The nearest two (A at 0.3, C at 0.45) are kept; B (0.6) is the one left out.
    expectRgbNear(r.at(kOverlap, kRow), over(kQuadA.color, over(kQuadC.color, kOpaque)), 1e-6f, "nearest two");
    // Under the cap elsewhere: exact.
    expectRgbNear(r.at(kOnlyB, kRow), over(kQuadB.color, kOpaque), 1e-6f, "only B");
}

// A cap so large that each band is one row: banding changes nothing.
TEST(Reference, OneRowBandsGiveTheSameImage) {
    TechniqueOptions options;
    options.referenceFragmentsPerPixel = std::size_t(1) << 20;
    ReferenceRun banded({kQuadA, kQuadB, kQuadC}, options);
    ReferenceRun whole({kQuadA, kQuadB, kQuadC});
    EXPECT_EQ(banded.image.values, whole.image.values);
    EXPECT_EQ(banded.technique->referenceReport()->fragments, whole.technique->referenceReport()->fragments);
}

TEST(Reference, IsTheSameForAnyThreadCount) {
    std::vector<std::vector<float>> images;
    for (int threads : {1, 2}) {
        auto backend = soft::createSoftBackend({.threads = threads, .tileSize = 8});
        auto technique = createTechnique(TechniqueKind::Reference, *backend, {});
        TechniqueFrame f(*backend, 1, {kQuadA, kQuadB, kQuadC});
        images.push_back(f.run(*technique).values);
    }
    EXPECT_EQ(images[0], images[1]);
}

TEST(Reference, RejectsAZeroCap) {
    auto backend = soft::createSoftBackend({});
    TechniqueOptions options;
    options.referenceFragmentsPerPixel = 0;
    EXPECT_THROW(createTechnique(TechniqueKind::Reference, *backend, options), engine::Error);
}

}  // namespace
