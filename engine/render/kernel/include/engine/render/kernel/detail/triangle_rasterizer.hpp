// SPDX-License-Identifier: MIT
#pragma once
// The tile rasterizer for one program type (program-authoring header): coverage per 8x8
// block, early depth, the program's shade(), alpha test with the GS fail modes,
// alpha-to-coverage and blending, in submission order within a tile. A program opts into
// the fast paths by what it offers (see kernel/programs.hpp); a module instantiates this
// template for its own program in its own translation unit (kernel/program_kernel.hpp), so
// no virtual call happens per fragment.
//
// TriangleRasterizer is one class template whose members are defined by stage, in
// kernel/rasterizer/:
//   rasterizer_class.hpp    the class, its per-draw set-up and the walk over a tile's blocks
//   coverage.hpp            which pixels and samples of a block a triangle covers
//   shading.hpp             per pixel: depth, shade(), alpha-to-coverage, alpha test, blend
//   constant_fragment.hpp   triangles whose fragment is the same everywhere, shaded once
//   fast_rows.hpp           the row paths of programs with fast-path hooks
// Every member is inline with internal linkage in the translation unit that includes this
// (an anonymous namespace, as raster_support.hpp's), exactly as when they were written in the
// class body: the compiler sees the whole rasterizer where it instantiates it.
#include "engine/render/kernel/detail/rasterizer/rasterizer_class.hpp"

#include "engine/render/kernel/detail/rasterizer/constant_fragment.hpp"
#include "engine/render/kernel/detail/rasterizer/coverage.hpp"
#include "engine/render/kernel/detail/rasterizer/fast_rows.hpp"
#include "engine/render/kernel/detail/rasterizer/shading.hpp"
