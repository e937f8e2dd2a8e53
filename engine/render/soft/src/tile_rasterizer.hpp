#pragma once
// Rasterizes the triangles binned to one tile, in submission order: tile -> 8x8 block
// -> pixel coverage with trivial reject/accept per block (llvmpipe's lp_rast_tri.c
// scheme), depth test before shading (our programs never change depth, so early depth is
// always exact), then alpha test with GS fail modes, alpha-to-coverage and blending.
#include <cstdint>
#include <span>
#include <vector>

#include "draw_state.hpp"
#include "engine/render/raster_state.hpp"
#include "triangle_setup.hpp"

namespace engine::render::soft {

struct TileCounters {
    std::uint64_t pixelsShaded = 0;
    std::uint64_t pixelsTouched = 0;
};

void rasterizeTile(const Rect& tile, std::span<const std::uint32_t> triangleIndices,
                   const std::vector<SetupTriangle>& triangles, const std::vector<DrawState>& draws,
                   TileCounters& counters);

}  // namespace engine::render::soft
