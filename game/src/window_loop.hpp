// SPDX-License-Identifier: MIT
#pragma once
// racer's window: frames rendered by a FrameRenderer (on the GL backend of the window, on the
// soft backend and uploaded to a GL texture to be shown, or on the Vulkan backend presenting
// to its window: loop_window.hpp), presented until the window
// closes, Esc is pressed or `frames` have been shown. The frame is rendered at the window's
// framebuffer size: a resize makes the frame's targets anew and the camera takes the new
// aspect; a minimised window renders nothing and waits for events. Keys: window_keys.hpp;
// with the free camera they (and the mouse, right button held) fly it from the headless
// overview pose, and its final pose is printed ("racer: free camera at (x, y, z), ...").
// The title bar (and the HUD, key H) show technique, camera (and its keys), render size,
// fps and per-pass milliseconds, averaged over a quarter of a second.
#include <string>

#include "engine/render/backend.hpp"
#include "frame_renderer.hpp"
#include "frame_source.hpp"
#include "loop_window.hpp"
#include "racer_options.hpp"

namespace racer {

struct WindowLoopSettings {
    int frames = 0;        // 0: until closed
    double fixedDt = 0.0;  // 0: the wall clock's step (at most 0.1 s)
    CameraMode camera = CameraMode::Chase;
    std::string script;  // parseWindowScript's format (racer --script)
    bool hud = false;    // the HUD shown from the first frame (H toggles it)
    // V turns the compare on with this technique on the right (B steps it); the frame may
    // start comparing (FrameRenderer::setCompare).
    transparency::TechniqueKind compareWith = transparency::TechniqueKind::AlphaTest;
};

struct WindowLoopResult {
    int frames = 0;
    double meanFrameMs = 0.0;
};

// `window` shows the frames `renderer` draws (loop_window.hpp). Technique keys that fail (not runnable here, not implemented yet)
// print the engine::Error and keep the current technique; a render size the backend refuses
// is reported and the frame keeps its last size (scaled to the window).
WindowLoopResult runWindowLoop(LoopWindow& window, engine::render::Backend& renderer, FrameRenderer& frame,
                               const FrameSource& source, const WindowLoopSettings& settings);

}  // namespace racer
