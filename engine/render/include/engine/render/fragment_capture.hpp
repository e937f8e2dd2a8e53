// SPDX-License-Identifier: MIT
#pragma once
// Fragment capture: a capability a backend may offer (Backend::fragmentCapture; the soft
// backend does, GL does not). Draws recorded while a sink is set hand every fragment that
// passes the depth (and alpha) test to the sink instead of writing colour or depth — what the
// exact transparency reference sorts and composites (modules/transparency).
#include <glm/glm.hpp>

namespace engine::render {

struct CapturedFragment {
    float depth = 0.0f;     // the pixel-centre depth the depth test compared
    glm::vec4 color{0.0f};  // the program's output, straight alpha, before any blending
};

// add() is called concurrently for pixels of different tiles, never for one pixel from two
// threads (a tile is rasterized by one thread, in submission order), so per-pixel storage
// needs no locking and the result does not depend on the thread count.
class FragmentSink {
public:
    virtual ~FragmentSink() = default;
    virtual void add(int x, int y, const CapturedFragment& fragment) = 0;
};

class FragmentCapture {
public:
    virtual ~FragmentCapture() = default;
    // Draws recorded while a sink is set go to it and write nothing. They must be in a
    // single-sampled pass and depth-tested (engine::Error otherwise). Null: draw normally.
    virtual void setFragmentSink(FragmentSink* sink) = 0;
};

}  // namespace engine::render
