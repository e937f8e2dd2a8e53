// SPDX-License-Identifier: MIT
#pragma once
// The closed race track: a seeded loop of control points joined by a Catmull-Rom spline,
// parameterised by arc length so the car drives at a constant speed, draped over the
// terrain's height field.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "engine/render/vertex.hpp"

namespace racer {

// Gentle rolling hills, the same function for the terrain mesh and the track.
float terrainHeight(float x, float z);

class Track {
public:
    explicit Track(std::uint32_t seed);

    float length() const { return length_; }
    glm::vec3 position(float distance) const;  // on the road surface, distance wraps around the loop
    glm::vec3 forward(float distance) const;   // unit tangent
    float width() const { return 12.0f; }

    // A ribbon mesh of the road, uv.v running along the track in metres / 10.
    void buildRoad(std::vector<engine::render::Vertex>& vertices, std::vector<std::uint32_t>& indices) const;

private:
    std::vector<glm::vec3> samples_;    // dense points along the spline
    std::vector<float> cumulative_;     // arc length at each sample
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
