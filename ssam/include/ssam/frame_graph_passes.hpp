// SPDX-License-Identifier: MIT
#pragma once
// SSAM as a frame-graph pass group (declared reads and writes: Falcor-style
// reflection of inputs and outputs): reads the opaque colour and depth, writes the
// composited colour and the foliage depth that later passes (grass, water, particles,
// light shafts) depth-test against ([Hathaway 2010] §3.7).
//
// With no foliage in view the mask and colour passes declare themselves empty, so the
// composite (which reads their outputs) is skipped too and the colour and depth flow
// through unchanged: SSAM costs nothing.
#include "engine/render/frame_graph.hpp"
#include "engine/render/frame_graph/color_depth.hpp"
#include "ssam/ssam.hpp"

namespace ssam {

// `frame` (the opaque colour and depth) must be backed by backend textures (imported, or
// transient textures from a backend allocator). `view` must outlive the graph's execute().
// Returns the composited colour (the opaque colour when empty) and the opaque + foliage
// depth. The pass names are "ssam mask", "ssam colour" and "ssam composite".
engine::render::ColorDepth addSsamPasses(engine::render::FrameGraph& graph, ScreenSpaceAlphaMask& ssam,
                                         const FoliageView& view, const engine::render::ColorDepth& frame);

}  // namespace ssam
