// SPDX-License-Identifier: MIT
#pragma once
// A frame's colour and depth as a frame graph knows them: the versions the next group of
// passes reads. A group that draws onto the frame takes these and returns the versions it
// left (a version it only read comes back unchanged), so the frame is threaded through
// every group in order and the graph sees who reads and writes what.
#include "engine/render/frame_graph/texture_handle.hpp"

namespace engine::render {

struct ColorDepth {
    FrameGraphTexture color;
    FrameGraphTexture depth;

    bool operator==(const ColorDepth&) const = default;
};

}  // namespace engine::render
