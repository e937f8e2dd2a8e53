// SPDX-License-Identifier: MIT
#pragma once
// SSAM as a frame-graph pass group (DESIGN.md "Data flow of one frame", Falcor-style
// reflection of inputs and outputs): reads the opaque colour and depth, writes the
// composited colour and the foliage depth that later passes (grass, water, particles,
// light shafts) depth-test against ([Hathaway 2010] §3.7).
//
// With no foliage in view the mask and colour passes declare themselves empty, so the
// composite (which reads their outputs) is skipped too and the colour and depth flow
// through unchanged: SSAM costs nothing.
#include "engine/render/frame_graph.hpp"
#include "ssam/ssam.hpp"

namespace ssam {

struct SsamGraphOutputs {
    engine::render::FrameGraphTexture color;  // composited colour (the opaque colour when empty)
    engine::render::FrameGraphTexture depth;  // opaque + foliage depth
};

// `color` and `depth` must be backed by backend textures (imported, or transient textures
// from backendTextureAllocator). `view` must outlive the graph's execute().
// The pass names are "ssam mask", "ssam colour" and "ssam composite".
SsamGraphOutputs addSsamPasses(engine::render::FrameGraph& graph, ScreenSpaceAlphaMask& ssam, const FoliageView& view,
                               engine::render::FrameGraphTexture color, engine::render::FrameGraphTexture depth);

}  // namespace ssam
