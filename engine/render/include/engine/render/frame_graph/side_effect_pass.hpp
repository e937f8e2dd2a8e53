// SPDX-License-Identifier: MIT
#pragma once
// The pass that ends a frame's graph: present, capture, readback. It reads the frame's
// colour and depth and is never culled (its effect is outside the graph), so everything
// that produced the frame survives culling.
#include <functional>
#include <string>

#include "engine/render/frame_graph/color_depth.hpp"

namespace engine::render {

class FrameGraph;

// `run` (may be empty) executes when the pass does, after every pass declared before it.
void addSideEffectPass(FrameGraph& graph, std::string name, const ColorDepth& frame, std::function<void()> run = {});

}  // namespace engine::render
