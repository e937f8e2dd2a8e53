// SPDX-License-Identifier: MIT
#pragma once
// The size racer's window renders at: its framebuffer's, followed on every resize, and what
// happens when the backend refuses a size.
#include <glm/glm.hpp>

#include "engine/core/error.hpp"
#include "frame_renderer.hpp"
#include "racer_options.hpp"

namespace racer {

// The framebuffer's own size (each side >= 1), scaled down as a whole (aspect kept) when a
// side exceeds engine::render::kMaxTextureDimension.
FrameSize renderSizeFor(int framebufferWidth, int framebufferHeight);

// Resizes a FrameRenderer to follow the framebuffer. A size the backend refuses, when the
// frame's targets are made or in the first frame drawn at it, is reported and the frame goes
// back to the last size that rendered; present scales it to the window.
class RenderSize {
public:
    explicit RenderSize(FrameRenderer& frame) : frame_(frame), rendered_(current()) {}

    FrameSize current() const { return {frame_.width(), frame_.height()}; }

    // Resizes the frame when the framebuffer has changed since the last call (a size refused
    // once is not tried again until the window changes).
    void follow(glm::ivec2 framebuffer);

    // The frame just drawn rendered at the current size.
    void rendered() { rendered_ = current(); }

    // A frame failed with `e`: at a size that has not rendered yet, goes back to the last one
    // that has and returns true; false when the size is not what is new.
    bool recover(const engine::Error& e);

private:
    void refused(FrameSize size, const engine::Error& e) const;

    FrameRenderer& frame_;
    FrameSize rendered_;
    glm::ivec2 seen_{-1, -1};
};

}  // namespace racer
