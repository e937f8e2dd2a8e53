// SPDX-License-Identifier: MIT
#include "ground.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>

namespace racer {

namespace {

float smoothstep(float edge0, float edge1, float x) {
    const float t = std::clamp((x - edge0) / (edge1 - edge0), 0.0f, 1.0f);
    return t * t * (3.0f - 2.0f * t);
}

}  // namespace

float landHeight(float x, float z) {
    // Hills only beyond the track (its loop stays inside ~320 m): a ring of ridges whose
    // height varies around the horizon, so the clearings look out onto wooded slopes.
    const float r = std::sqrt(x * x + z * z);
    const float rise = smoothstep(450.0f, 1100.0f, r);
    if (rise <= 0.0f) return terrainHeight(x, z);
    const float angle = std::atan2(z, x);
    const float ridges = 55.0f + 22.0f * std::sin(3.0f * angle + 0.7f) + 12.0f * std::sin(7.0f * angle + 2.1f) +
                         8.0f * std::sin(r * 0.006f + 5.0f * angle);
    return terrainHeight(x, z) + rise * ridges;
}

float Ground::Grid::interpolate(float x, float z) const {
    const float gx = std::clamp((x - origin) / cell, 0.0f, float(cells)),
                gz = std::clamp((z - origin) / cell, 0.0f, float(cells));
    const int ix = std::min(int(gx), cells - 1), iz = std::min(int(gz), cells - 1);
    const float fx = gx - float(ix), fz = gz - float(iz);
    // The two triangles of a cell as buildChunks() emits them: (x,z) (x,z+1) (x+1,z) and
    // (x+1,z) (x,z+1) (x+1,z+1), split along the diagonal from (x+1,z) to (x,z+1).
    if (fx + fz <= 1.0f) {
        const float h00 = at(ix, iz);
        return h00 + fx * (at(ix + 1, iz) - h00) + fz * (at(ix, iz + 1) - h00);
    }
    const float h11 = at(ix + 1, iz + 1);
    return h11 + (1.0f - fx) * (at(ix, iz + 1) - h11) + (1.0f - fz) * (at(ix + 1, iz) - h11);
}

glm::vec3 Ground::Grid::normal(int x, int z) const {
    // Central differences of the grid itself (one-sided at its border).
    const int x0 = std::max(x - 1, 0), x1 = std::min(x + 1, cells);
    const int z0 = std::max(z - 1, 0), z1 = std::min(z + 1, cells);
    const glm::vec3 dx(float(x1 - x0) * cell, at(x1, z) - at(x0, z), 0.0f);
    const glm::vec3 dz(0.0f, at(x, z1) - at(x, z0), float(z1 - z0) * cell);
    return glm::normalize(glm::cross(dz, dx));
}

Ground::Ground(const Track& track) {
    coarse_.origin = -kHalfSize;
    coarse_.cell = kCoarseCell;
    coarse_.cells = int(std::lround(2.0f * kHalfSize / kCoarseCell));
    coarse_.heights.resize(std::size_t(coarse_.cells + 1) * std::size_t(coarse_.cells + 1));
    for (int z = 0; z <= coarse_.cells; ++z)
        for (int x = 0; x <= coarse_.cells; ++x)
            coarse_.heights[std::size_t(z) * std::size_t(coarse_.cells + 1) + std::size_t(x)] =
                landHeight(coarse_.origin + coarse_.cell * float(x), coarse_.origin + coarse_.cell * float(z));

    fine_.origin = -kFineHalfSize;
    fine_.cell = kFineCell;
    fine_.cells = int(std::lround(2.0f * kFineHalfSize / kFineCell));
    fine_.heights.resize(std::size_t(fine_.cells + 1) * std::size_t(fine_.cells + 1));
    for (int z = 0; z <= fine_.cells; ++z)
        for (int x = 0; x <= fine_.cells; ++x) {
            const float px = fine_.origin + fine_.cell * float(x), pz = fine_.origin + fine_.cell * float(z);
            const bool border = x == 0 || z == 0 || x == fine_.cells || z == fine_.cells;
            // The border follows the coarse grid's edges exactly: no crack between the two.
            fine_.heights[std::size_t(z) * std::size_t(fine_.cells + 1) + std::size_t(x)] =
                border ? coarse_.interpolate(px, pz) : landHeight(px, pz);
        }
    cutCorridor(track);
}

void Ground::cutCorridor(const Track& track) {
    // For every fine vertex near the road: its distance to the centre line and the road's
    // height at the nearest point, found segment by segment over the vertices each touches.
    const std::size_t count = fine_.heights.size();
    std::vector<float> distance(count, std::numeric_limits<float>::infinity()), roadHeight(count, 0.0f);
    const float reach = kLevelHalfWidth + kBlendWidth;
    const std::vector<glm::vec3>& line = track.centreLine();
    for (std::size_t i = 0; i + 1 < line.size(); ++i) {
        const glm::vec3 a = line[i], b = line[i + 1];
        const glm::vec2 a2(a.x, a.z), ab(b.x - a.x, b.z - a.z);
        const float abLength2 = std::max(glm::dot(ab, ab), 1e-12f);
        const int x0 = std::max(0, int(std::floor((std::min(a.x, b.x) - reach - fine_.origin) / fine_.cell)));
        const int x1 = std::min(fine_.cells, int(std::ceil((std::max(a.x, b.x) + reach - fine_.origin) / fine_.cell)));
        const int z0 = std::max(0, int(std::floor((std::min(a.z, b.z) - reach - fine_.origin) / fine_.cell)));
        const int z1 = std::min(fine_.cells, int(std::ceil((std::max(a.z, b.z) + reach - fine_.origin) / fine_.cell)));
        for (int z = z0; z <= z1; ++z)
            for (int x = x0; x <= x1; ++x) {
                const glm::vec2 p(fine_.origin + fine_.cell * float(x), fine_.origin + fine_.cell * float(z));
                const float t = std::clamp(glm::dot(p - a2, ab) / abLength2, 0.0f, 1.0f);
                const float d = glm::length(p - (a2 + ab * t));
                const std::size_t k = std::size_t(z) * std::size_t(fine_.cells + 1) + std::size_t(x);
                if (d < distance[k]) {
                    distance[k] = d;
                    roadHeight[k] = a.y + (b.y - a.y) * t;
                }
            }
    }
    for (std::size_t k = 0; k < count; ++k) {
        if (!(distance[k] < reach)) continue;
        const float level = roadHeight[k] - kCorridorDrop;
        const float blend = smoothstep(kLevelHalfWidth, kLevelHalfWidth + kBlendWidth, distance[k]);
        fine_.heights[k] = level + (fine_.heights[k] - level) * blend;
    }
}

float Ground::height(float x, float z) const {
    const bool inFine = std::abs(x) <= kFineHalfSize && std::abs(z) <= kFineHalfSize;
    return inFine ? fine_.interpolate(x, z) : coarse_.interpolate(x, z);
}

void Ground::addCells(const Grid& grid, int x0, int z0, int x1, int z1, const Grid* hole, GroundChunk& chunk) {
    // Vertices of the chunk's (x1 - x0 + 1) x (z1 - z0 + 1) corners; cells inside `hole` skipped.
    const int row = x1 - x0 + 1;
    for (int z = z0; z <= z1; ++z)
        for (int x = x0; x <= x1; ++x) {
            engine::render::Vertex v;
            const float px = grid.origin + grid.cell * float(x), pz = grid.origin + grid.cell * float(z);
            v.position = {px, grid.at(x, z), pz};
            v.normal = grid.normal(x, z);
            v.uv = {px / 8.0f, pz / 8.0f};  // the ground texture repeats every 8 m
            chunk.vertices.push_back(v);
        }
    for (int z = z0; z < z1; ++z)
        for (int x = x0; x < x1; ++x) {
            if (hole) {
                const float cx = grid.origin + grid.cell * (float(x) + 0.5f),
                            cz = grid.origin + grid.cell * (float(z) + 0.5f);
                const float h = hole->origin + hole->cell * float(hole->cells);
                if (cx > hole->origin && cx < h && cz > hole->origin && cz < h) continue;
            }
            const std::uint32_t i = std::uint32_t((z - z0) * row + (x - x0)), r = std::uint32_t(row);
            chunk.indices.insert(chunk.indices.end(), {i, i + r, i + 1, i + 1, i + r, i + r + 1});
        }
}

std::vector<GroundChunk> Ground::buildChunks() const {
    std::vector<GroundChunk> chunks;
    for (const auto& [grid, step, hole] :
         {std::tuple{&fine_, 24, (const Grid*)nullptr}, std::tuple{&coarse_, 16, &fine_}})
        for (int z = 0; z < grid->cells; z += step)
            for (int x = 0; x < grid->cells; x += step) {
                GroundChunk chunk;
                addCells(*grid, x, z, std::min(x + step, grid->cells), std::min(z + step, grid->cells), hole, chunk);
                if (chunk.indices.empty()) continue;
                chunks.push_back(std::move(chunk));
            }
    return chunks;
}

}  // namespace racer
