// SPDX-License-Identifier: MIT
#pragma once
// Rasterizes the triangles binned to one tile, in submission order: tile -> 8x8 block
// -> pixel coverage with trivial reject/accept per block (llvmpipe's lp_rast_tri.c
// scheme), depth test before shading (our programs never change depth, so early depth is
// always exact), then alpha test with GS fail modes, alpha-to-coverage and blending.
#include <cstdint>
#include <span>
#include <vector>

#include "engine/render/kernel/detail/draw_state.hpp"
#include "engine/render/kernel/detail/triangle_rasterizer.hpp"
#include "engine/render/raster_state.hpp"
#include "engine/render/kernel/detail/triangle_setup.hpp"

namespace engine::render::soft {

// The sample positions of a pass with `samples` samples (1, 2, 4 or 8; others: 1).
const SamplePattern& samplePattern(int samples);

void rasterizeTile(const Rect& tile, std::span<const SetupTriangle* const> triangles,
                   const std::vector<DrawState>& draws, TileCounters& counters);

// Tiles of the pass's grid.
struct TileGrid {
    int tileSize = 64;
    int tilesX = 0, tilesY = 0;
};

// One binned triangle: tile index (y * tilesX + x) and the triangle's index in its chunk.
struct BinEntry {
    std::uint32_t tile;
    std::uint32_t triangle;
};

// Whether a triangle's pixel box is at most 2x2 pixels, and whether such a triangle covers a
// sample of `pattern` (the rasterizer's own per-sample edge test, sampleCoverage): many tiny
// triangles cover none, and are best dropped before any more work is spent on them.
bool isTinyTriangle(const SetupTriangle& t);
bool coversAnySample(const SetupTriangle& t, const SamplePattern& pattern);

// Appends an entry for each tile that the triangle's bounding box meets and no edge
// rejects as a whole (the block test of the rasterizer over the tile: a skipped tile is
// one the rasterizer would find no covered sample in). A triangle whose box is at most
// 2x2 pixels is tested sample by sample and not binned at all when it covers none.
void binTriangle(const SetupTriangle& t, std::uint32_t triangle, const TileGrid& grid, std::vector<BinEntry>& out);

}  // namespace engine::render::soft
