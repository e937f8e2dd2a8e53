#pragma once
// racer's window: frames rendered by a FrameRenderer (on the GL backend of the window, or on
// the soft backend and uploaded to a GL texture to be shown), presented until the window
// closes, Esc is pressed or `frames` have been shown. Keys: window_keys.hpp; with the free
// camera they (and the mouse, right button held) fly it from the headless overview pose, and
// its final pose is printed ("racer: free camera at (x, y, z), ..."). The title bar shows
// technique, camera (and the fly keys), fps and per-pass milliseconds, four times a second.
#include <string>

#include "engine/render/gl/gl_backend.hpp"
#include "frame_renderer.hpp"
#include "frame_source.hpp"

namespace racer {

struct WindowLoopSettings {
    int frames = 0;          // 0: until closed
    double fixedDt = 0.0;    // 0: the wall clock's step (at most 0.1 s)
    CameraMode camera = CameraMode::Chase;
    float aspect = 16.0f / 9.0f;  // of the rendered frame (present scales it to the window)
    std::string keyScript;   // parseKeyScript's format
};

struct WindowLoopResult {
    int frames = 0;
    double meanFrameMs = 0.0;
};

// `presenter` is the GL backend owning the window's context; `renderer` draws the frames and
// is either the same backend or another one (soft), whose colour is then read back and
// uploaded each frame. Technique keys that fail (not runnable here, not implemented yet)
// print the engine::Error and keep the current technique.
WindowLoopResult runWindowLoop(engine::render::gl::GlfwWindowContext& window, engine::render::gl::GlBackend& presenter,
                               engine::render::Backend& renderer, FrameRenderer& frame, const FrameSource& source,
                               const WindowLoopSettings& settings);

}  // namespace racer
