// SPDX-License-Identifier: MIT
#pragma once
// The racing scene's ground: the rolling hills of terrainHeight() near the track, rising into
// wooded hills towards the horizon (the vista of [Hathaway 2010] §3.1), and cut into a level
// corridor under the road so that no ground rises above the asphalt anywhere on the lap.
//
// Two height grids make it: a fine one over the square that holds the track, whose cells are
// small enough that every triangle under the road has all its corners in the level corridor,
// and a coarse one out to the horizon with a hole where the fine one lies. The fine grid's
// border takes the coarse grid's heights, so the two meet without a crack. height() interpolates
// exactly as the mesh's triangles do: what is placed on the ground stands on what is drawn.
#include <vector>

#include "engine/render/vertex.hpp"
#include "track.hpp"

namespace racer {

// The land before the road is cut in: terrainHeight() plus hills that rise from 450 m out.
float landHeight(float x, float z);

// One piece of the ground mesh (a square of cells), drawn and culled on its own.
struct GroundChunk {
    std::vector<engine::render::Vertex> vertices;
    std::vector<std::uint32_t> indices;
};

class Ground {
public:
    // The ground for `track`: level at kCorridorDrop below the road out to kLevelHalfWidth
    // from the centre line, then blending into the land over kBlendWidth.
    explicit Ground(const Track& track);

    static constexpr float kHalfSize = 2000.0f;             // the whole ground, metres from the origin
    static constexpr float kCoarseCell = 25.0f;             // out to the horizon
    static constexpr float kFineHalfSize = 350.0f;          // the square around the track
    static constexpr float kFineCell = kCoarseCell / 6.0f;  // ~4.2 m: 6 fine cells per coarse one
    static constexpr float kCorridorDrop = 0.25f;           // the level corridor below the asphalt
    // Road half width (6 m) plus a fine cell's diagonal (5.9 m): any triangle with a corner
    // under the road has all three corners in the level part.
    static constexpr float kLevelHalfWidth = 12.5f;
    static constexpr float kBlendWidth = 14.0f;

    // The ground's height at (x, z), as the mesh draws it (inside kHalfSize).
    float height(float x, float z) const;

    // The mesh in chunks of at most 24 x 24 fine or 16 x 16 coarse cells.
    std::vector<GroundChunk> buildChunks() const;

private:
    struct Grid {
        float origin = 0.0f;  // x and z of vertex (0, 0)
        float cell = 1.0f;
        int cells = 0;  // per side; (cells + 1)^2 vertices
        std::vector<float> heights;
        float at(int x, int z) const { return heights[std::size_t(z) * std::size_t(cells + 1) + std::size_t(x)]; }
        float interpolate(float x, float z) const;
        glm::vec3 normal(int x, int z) const;
    };
    void cutCorridor(const Track& track);
    static void addCells(const Grid& grid, int x0, int z0, int x1, int z1, const Grid* hole, GroundChunk& chunk);

    Grid coarse_, fine_;
};

}  // namespace racer
