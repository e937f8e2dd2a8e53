// SPDX-License-Identifier: MIT
#pragma once
// SSAM as a frame-graph pass group (declared reads and writes: Falcor-style
// reflection of inputs and outputs): reads the opaque colour and depth, writes the
// composited colour and the foliage depth that later passes (grass, water, particles,
// light shafts) depth-test against ([Hathaway 2010] §3.7).
//
// SSAM's intermediate targets (rt_mask or rt_mask_max + rt_mask_add, rt_foliage) are the
// graph's transients: the mask pass creates the mask, the colour pass rt_foliage, the
// composite is their last reader, and the graph's allocator backs them only in between
// (ScreenSpaceAlphaMask makes none of its own here). A later pass that reads them (a
// capture) keeps them alive until it has run.
//
// With no foliage in view the mask and colour passes declare themselves empty, so the
// composite (which reads their outputs) is skipped too and the colour and depth flow
// through unchanged: SSAM costs nothing, and no target is allocated.
#include "engine/render/frame_graph.hpp"
#include "engine/render/frame_graph/color_depth.hpp"
#include "ssam/ssam.hpp"

namespace ssam {

struct SsamPasses {
    engine::render::ColorDepth frame;  // the composited colour (the opaque colour when empty), opaque + foliage depth
    // The versions of the intermediates the passes wrote; all invalid when no foliage is in
    // view (nothing to read), maskAdd valid only with RG16F mask precision.
    engine::render::FrameGraphTexture mask, maskAdd, foliage;
};

// `frame` (the opaque colour and depth) must be backed by backend textures (imported, or
// transient textures from a backend allocator), and the graph executed with an allocator
// backed by ssam.backend() (a TransientTexturePool). `view` must outlive the graph's
// execute(). The pass names are "ssam mask", "ssam colour" and "ssam composite".
SsamPasses addSsamPasses(engine::render::FrameGraph& graph, ScreenSpaceAlphaMask& ssam, const FoliageView& view,
                         const engine::render::ColorDepth& frame);

}  // namespace ssam
