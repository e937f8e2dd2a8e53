// SPDX-License-Identifier: MIT
#pragma once
// What racer's loops (headless and window) ask the world for each frame: advance the
// simulation by dt, then the draw lists seen from the chosen camera. racer.cpp builds it
// for the racing scene or a --scene glTF file.
#include <functional>

#include "camera_rig.hpp"
#include "engine/scene/draw_lists.hpp"
#include "window_keys.hpp"

namespace racer {

struct SceneFrame {
    CameraView camera;
    engine::scene::DrawLists lists;
};

// What the player does in the window this frame (headless runs pass the default: the
// overview, the autopilot driving).
struct PlayerInput {
    FreeCamera free;         // the free camera's pose, used when `camera` is CameraMode::Free
    HeldDriveKeys drive;     // the drive keys held (chase camera only): any takes the wheel
    bool autopilot = false;  // R was pressed: the autopilot drives again
};

// time: simulated seconds at this frame; dt: the step just taken (0 while paused).
using FrameSource =
    std::function<SceneFrame(float time, float dt, CameraMode camera, const PlayerInput& input, float aspect)>;

}  // namespace racer
