// SPDX-License-Identifier: MIT
#pragma once
// The closed race track: a seeded loop of control points joined by a Catmull-Rom spline,
// parameterised by arc length so the car drives at a constant speed. Its height follows the
// terrain smoothed along the lap (gentle grades, level across the road); the racing scene's
// ground (ground.hpp) is cut down to it.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "engine/render/vertex.hpp"

namespace racer {

// Gentle rolling hills: the land the track is laid over (ground.hpp), and ssam-bench's terrain.
float terrainHeight(float x, float z);

class Track {
public:
    explicit Track(std::uint32_t seed);

    float length() const { return length_; }
    glm::vec3 position(float distance) const;  // on the road surface, distance wraps around the loop
    glm::vec3 forward(float distance) const;   // unit tangent
    float width() const { return 12.0f; }
    // The dense points along the spline, on the road surface; the last repeats the first.
    const std::vector<glm::vec3>& centreLine() const { return samples_; }
    // The point of the centre line nearest to p (horizontally): how far along the lap it is
    // and how far p is from it. Brute force over the samples: for set-up and tests.
    struct Nearest {
        float distance = 0.0f;  // along the lap, metres
        float offset = 0.0f;    // horizontal metres from the centre line
    };
    Nearest nearest(const glm::vec3& p) const;

    // A ribbon mesh of the road, level across its width, uv.v running along the track in
    // metres / 10.
    void buildRoad(std::vector<engine::render::Vertex>& vertices, std::vector<std::uint32_t>& indices) const;
    // Gravel shoulders on both sides: from just under the road's edge, kShoulderWidth out and
    // down to `drop` + 5 cm below the road (into the ground beside it), so the edge of the
    // asphalt is a clean line whatever the ground does. uv.u spans 0.2 .. 0.4 (the track
    // texture's plain grit), uv.v as the road's.
    static constexpr float kShoulderWidth = 1.6f;
    void buildShoulders(float drop, std::vector<engine::render::Vertex>& vertices,
                        std::vector<std::uint32_t>& indices) const;

private:
    std::vector<glm::vec3> samples_;  // dense points along the spline
    std::vector<float> cumulative_;   // arc length at each sample
    float length_ = 0.0f;
};

// A square grid of the terrain height field centred on the origin.
void buildTerrain(float halfSize, int cells, std::vector<engine::render::Vertex>& vertices,
                  std::vector<std::uint32_t>& indices);

// Deterministic PRNG for placement (the same numbers on every platform and library).
class Random {
public:
    explicit Random(std::uint64_t seed) : state_(seed * 0x9E3779B97F4A7C15ull + 1) {}
    std::uint32_t next();
    float uniform(float lo, float hi) { return lo + (hi - lo) * float(next() >> 8) * (1.0f / 16777216.0f); }

private:
    std::uint64_t state_;
};

}  // namespace racer
