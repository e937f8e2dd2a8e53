// SPDX-License-Identifier: MIT
// The racing scene's ground (game/src/ground.hpp) fits the road: nowhere on the lap does the
// ground mesh rise above the asphalt (were it to, at 1280x720 it would poke through along the
// inside of the road), the shoulders reach down into the ground on both sides,
// and Ground::height() is the height the mesh draws, so what is placed on the ground stands
// on it.
#include <gtest/gtest.h>

#include <cmath>

#include "ground.hpp"
#include "track.hpp"

namespace {

using racer::Ground;
using racer::Track;
using engine::render::Vertex;

float barycentricHeight(const Vertex& a, const Vertex& b, const Vertex& c, float u, float v) {
    return a.position.y + u * (b.position.y - a.position.y) + v * (c.position.y - a.position.y);
}

glm::vec3 barycentricPoint(const Vertex& a, const Vertex& b, const Vertex& c, float u, float v) {
    return a.position + u * (b.position - a.position) + v * (c.position - a.position);
}

class GroundFitsTheRoad : public ::testing::TestWithParam<std::uint32_t> {};

// Every triangle of the road mesh, sampled on a 10 x 10 barycentric grid (about 0.4 m apart
// along, 1.2 m across): the ground below each point is at least 10 cm under the asphalt.
TEST_P(GroundFitsTheRoad, NoGroundAboveTheAsphaltAnywhereOnTheLap) {
    const Track track(GetParam());
    const Ground ground(track);
    std::vector<Vertex> vertices;
    std::vector<std::uint32_t> indices;
    track.buildRoad(vertices, indices);
    ASSERT_GT(indices.size(), 600u);
    constexpr int kSteps = 10;
    float closest = 1e30f;
    glm::vec3 where(0.0f);
    std::size_t samples = 0;
    for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
        const Vertex& a = vertices[indices[t]];
        const Vertex& b = vertices[indices[t + 1]];
        const Vertex& c = vertices[indices[t + 2]];
        for (int i = 0; i <= kSteps; ++i)
            for (int j = 0; i + j <= kSteps; ++j) {
                const float u = float(i) / kSteps, v = float(j) / kSteps;
                const glm::vec3 p = barycentricPoint(a, b, c, u, v);
                const float clearance = barycentricHeight(a, b, c, u, v) - ground.height(p.x, p.z);
                ++samples;
                if (clearance < closest) closest = clearance, where = p;
            }
    }
    EXPECT_GE(closest, 0.10f) << "the ground comes within " << closest << " m of the asphalt (or above it) at ("
                              << where.x << ", " << where.z << "), over " << samples << " samples";
}

// The shoulders run from under the asphalt's edge out and down into the ground: their outer
// edge is below the ground (no gap to see through), their inner edge above it.
TEST_P(GroundFitsTheRoad, ShouldersReachIntoTheGround) {
    const Track track(GetParam());
    const Ground ground(track);
    std::vector<Vertex> vertices;
    std::vector<std::uint32_t> indices;
    track.buildShoulders(Ground::kCorridorDrop, vertices, indices);
    ASSERT_EQ(vertices.size() % 2, 0u);
    for (std::size_t i = 0; i < vertices.size(); ++i) {
        const glm::vec3 p = vertices[i].position;
        const float above = p.y - ground.height(p.x, p.z);
        if (i % 2 == 0) EXPECT_GT(above, 0.1f) << "inner edge at (" << p.x << ", " << p.z << ")";
        else EXPECT_LT(above, 0.0f) << "outer edge at (" << p.x << ", " << p.z << ")";
    }
}

// The road is level across (both edges at the centre line's height) with gentle grades along.
TEST_P(GroundFitsTheRoad, RoadIsLevelAcrossAndGentleAlong) {
    const Track track(GetParam());
    std::vector<Vertex> vertices;
    std::vector<std::uint32_t> indices;
    track.buildRoad(vertices, indices);
    for (std::size_t i = 0; i + 1 < vertices.size(); i += 2)
        EXPECT_FLOAT_EQ(vertices[i].position.y, vertices[i + 1].position.y) << "road row " << i / 2;
    float steepest = 0.0f;
    for (float d = 0.0f; d < track.length(); d += 2.0f) {
        const glm::vec3 a = track.position(d), b = track.position(d + 2.0f);
        steepest = std::max(steepest, std::abs(b.y - a.y) / glm::length(glm::vec2(b.x - a.x, b.z - a.z)));
    }
    EXPECT_LT(steepest, 0.12f);
}

INSTANTIATE_TEST_SUITE_P(Seeds, GroundFitsTheRoad, ::testing::Values(1u, 2u, 7u, 12345u));

// height() is the mesh: at the corners of every chunk's triangles it is the vertex's height,
// and inside a triangle the plane through its corners (sampled at three inner points each).
TEST(Ground, HeightIsWhatTheMeshDraws) {
    const Track track(1);
    const Ground ground(track);
    const std::vector<racer::GroundChunk> chunks = ground.buildChunks();
    ASSERT_GT(chunks.size(), 40u);
    std::size_t triangles = 0;
    for (const racer::GroundChunk& chunk : chunks)
        for (std::size_t t = 0; t + 2 < chunk.indices.size(); t += 3) {
            const Vertex& a = chunk.vertices[chunk.indices[t]];
            const Vertex& b = chunk.vertices[chunk.indices[t + 1]];
            const Vertex& c = chunk.vertices[chunk.indices[t + 2]];
            ++triangles;
            for (const Vertex* v : {&a, &b, &c})
                ASSERT_NEAR(ground.height(v->position.x, v->position.z), v->position.y, 1e-3f);
            for (const glm::vec2 uv : {glm::vec2(0.2f, 0.2f), glm::vec2(0.6f, 0.2f), glm::vec2(0.2f, 0.6f)}) {
                const glm::vec3 p = barycentricPoint(a, b, c, uv.x, uv.y);
                ASSERT_NEAR(ground.height(p.x, p.z), p.y, 2e-3f)
                    << "inside a triangle at (" << p.x << ", " << p.z << ")";
            }
        }
    EXPECT_GT(triangles, 100000u);
}

// Far from the track the land rises into hills (the vista beyond the clearings); near it the
// ground is the gentle terrain the track was laid over.
TEST(Ground, HillsRiseBeyondTheTrack) {
    const Track track(1);
    const Ground ground(track);
    float highestFar = -1e30f;
    for (int i = 0; i < 64; ++i) {
        const float angle = 6.2832f * float(i) / 64.0f;
        highestFar = std::max(highestFar, ground.height(1300.0f * std::cos(angle), 1300.0f * std::sin(angle)));
    }
    EXPECT_GT(highestFar, 50.0f);
    EXPECT_NEAR(ground.height(60.0f, -40.0f), racer::terrainHeight(60.0f, -40.0f), 0.05f);
}

}  // namespace
