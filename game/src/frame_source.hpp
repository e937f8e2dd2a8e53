// SPDX-License-Identifier: MIT
#pragma once
// What racer's loops (headless and window) ask the world for each frame: advance the
// simulation by dt, then the draw lists seen from the chosen camera. racer.cpp builds it
// for the racing scene or a --scene glTF file.
#include <functional>

#include "camera_rig.hpp"
#include "engine/scene/draw_lists.hpp"

namespace racer {

struct SceneFrame {
    CameraView camera;
    engine::scene::DrawLists lists;
};

// time: simulated seconds at this frame; dt: the step just taken (0 while paused); free: the
// free camera's pose, used when `camera` is CameraMode::Free (the window flies it; headless
// runs pass the default, the overview).
using FrameSource =
    std::function<SceneFrame(float time, float dt, CameraMode camera, const FreeCamera& free, float aspect)>;

}  // namespace racer
