// SPDX-License-Identifier: MIT
#pragma once
// Procedural meshes of the committed content: trees and bushes built as in Pure ([Hathaway 2010]
// §3.3, Fig. 3.2: "a multitude of polygonal planes ... oriented as randomly as possible",
// intersecting, around a trunk), and the props of the racing scene. Units are metres, +Y up,
// +Z forward (the glTF convention), UV origin top-left.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "prng.hpp"

namespace content {

struct MeshData {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;
    std::vector<glm::vec2> uvs;
    std::vector<std::uint32_t> indices;  // triangles, counter-clockwise seen from the normal's side

    std::size_t vertexCount() const { return positions.size(); }
    std::uint32_t addVertex(glm::vec3 p, glm::vec3 n, glm::vec2 uv);
    // Two triangles p0 p1 p2, p0 p2 p3, wound to face `normal` whatever order the corners come in.
    void addQuad(const glm::vec3 (&p)[4], glm::vec3 normal, const glm::vec2 (&uv)[4]);
};

// A tapered open cylinder along +Y from y0 to y1 (the trunk); u wraps `uRepeat` times around,
// v runs 1 per circumference up the height.
MeshData trunk(float y0, float y1, float radius0, float radius1, int sides, float uRepeat);

// One lobe of a crown: `quads` square cards of random size in [sizeMin, sizeMax], centred at
// random points inside the ellipsoid (centre, radii), each facing a uniformly random direction
// with a random roll. Normals bend outwards from the lobe's centre (60% radial, 40% face), the
// usual trick that lets a cloud of cards shade like one rounded mass.
struct Lobe {
    glm::vec3 centre;
    glm::vec3 radii;
    int quads;
    float sizeMin;
    float sizeMax;
};
void addCrownLobe(MeshData& mesh, Pcg32& rng, const Lobe& lobe);

// Fronds radiating from `top`: `count` cards whose stem (texture bottom-centre) sits at the
// top, reaching out `length` metres at an elevation in [minElevation, maxElevation] radians
// above the horizon, with a random roll about the stem.
void addFronds(MeshData& mesh, Pcg32& rng, glm::vec3 top, int count, float length, float minElevation,
               float maxElevation);

// An axis-aligned box with per-face normals; every face maps to the UV rectangle `uvRect`
// (u0, v0, u1, v1), or `sideRect` for the four sides when given.
void addBox(MeshData& mesh, glm::vec3 min, glm::vec3 max, glm::vec4 uvRect, glm::vec4 sideRect);

// A closed cylinder along X (a wheel), mapped to `uvRect`.
void addWheel(MeshData& mesh, glm::vec3 centre, float radius, float width, int sides, glm::vec4 uvRect);

// A flat disc at y = 0 facing +Y, UV = the unit square over its bounding square.
MeshData disc(float radius, int segments);

// A square terrain patch of `size` metres and `cells` x `cells` quads centred on the origin,
// heights from fractal noise of amplitude `relief`; UV repeats every `uvMetres`.
MeshData terrainPatch(float size, int cells, float relief, float uvMetres, std::uint32_t seed);

// A closed track: a Catmull-Rom loop through `control` points, sampled `samplesPerSpan` times
// per span; the ribbon is `width` wide, u across it, v = distance / width along it.
struct TrackShape {
    std::vector<glm::vec3> control;
    std::vector<glm::vec3> centreLine;  // the sampled loop (first point not repeated)
    float width = 0.0f;
};
TrackShape trackShape(std::uint32_t seed, int controlPoints, glm::vec2 radii, int samplesPerSpan, float width);
MeshData trackRibbon(const TrackShape& shape);

}  // namespace content
