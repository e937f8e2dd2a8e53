// SPDX-License-Identifier: MIT
#pragma once
// The window's keys, as pure functions of GLFW key codes so they are unit-tested without a
// window: 1-8 pick a technique (transparency::allTechniques() order), T / Shift+T step to
// the next / previous one, C cycles the camera (chase, pan, free), P pauses the simulation,
// H shows or hides the HUD, V the side-by-side compare, B steps the compared (right)
// technique, R gives the car back to the autopilot, Esc quits. With the chase camera, held keys drive
// the car (driveControls; the first one takes it over from the autopilot): W/Up accelerate,
// S/Down brake and reverse, A/Left and D/Right steer. With the free camera, held keys fly
// it (flyControls): W/S forward/back, A/D strafe, Q/E or Ctrl/Space down/up, the arrows
// turn, Shift is faster; the window adds mouse look while the right button is held. A window script (`racer --script`, hidden: for
// tests) presses or holds keys at given frames, and resizes or minimises the window.
#include <functional>
#include <string>
#include <vector>

#include "camera_rig.hpp"
#include "car_driver.hpp"

namespace racer {

enum class WindowAction {
    None,
    Quit,
    SelectTechnique,
    NextTechnique,
    PreviousTechnique,
    NextCamera,
    TogglePause,
    Autopilot,  // the autopilot drives the car again
    ToggleHud,
    ToggleCompare,
    NextCompared,
};

struct KeyAction {
    WindowAction action = WindowAction::None;
    int technique = -1;  // SelectTechnique: index into transparency::allTechniques()
};

// `key` is a GLFW_KEY_* code (the top row's digits and the keypad's both select).
KeyAction actionForKey(int key, bool shift);

// The GLFW keys the window polls for presses (every key actionForKey maps to an action).
const std::vector<int>& watchedKeys();

// The car's controls from the keys held now (`held(GLFW_KEY_*)`); opposite keys cancel.
// `any` is whether a drive key is held at all (the player takes the wheel).
struct HeldDriveKeys {
    DriveControls controls;
    bool any = false;
};
HeldDriveKeys driveControls(const std::function<bool(int key)>& held);

// The GLFW keys driveControls reads (polled every frame with the chase camera).
const std::vector<int>& driveKeys();

// The drive keys in one line, for the title bar and the console.
const char* driveKeysHelp();

// The free camera's controls from the keys held now (`held(GLFW_KEY_*)`); opposite keys
// cancel. None of these keys has an action, so flying never switches technique or camera.
FlyControls flyControls(const std::function<bool(int key)>& held);

// The GLFW keys flyControls reads (the window polls them every frame with the free camera).
const std::vector<int>& flyKeys();

// The fly keys in one line, for the title bar and the console.
const char* flyKeysHelp();

struct ScriptedKey {
    int frame = 0;      // pressed before this frame is rendered (0 = the first frame)
    int lastFrame = 0;  // held down to this frame (inclusive); == frame for a plain press
    int key = 0;        // GLFW_KEY_*
    bool shift = false;
};

// What a user does to the window itself, before `frame` is rendered: resize it to width x
// height (screen coordinates; the render size follows its framebuffer), or, with
// minimizeMs > 0, minimise it and restore it that many milliseconds later.
struct ScriptedWindowChange {
    int frame = 0;
    int width = 0, height = 0;
    int minimizeMs = 0;
};

struct WindowScript {
    std::vector<ScriptedKey> keys;              // sorted by first frame
    std::vector<ScriptedWindowChange> changes;  // sorted by frame
};

// "FRAME:ENTRY,FIRST-LAST:KEY..." with ENTRY a KEY, size=WxH (each side 1..32767) or
// minimize=MS (1..60000 ms), and KEY one of 1-8, T, C, P, R, H, V, B, Esc, W, A, S, D, Q, E, Space, Ctrl,
// Left, Right, Up, Down, each optionally "shift+"-prefixed; FIRST-LAST holds the key for those
// frames (inclusive), e.g. "2:3,4:C,0-9:W,10-14:shift+D,5:size=400x300,8:minimize=200,20:Esc".
// Throws engine::Error naming the bad entry.
WindowScript parseWindowScript(const std::string& script);

// Whether the script holds `key` at `frame`; GLFW_KEY_LEFT_SHIFT is held by every held
// "shift+" entry (so "0-9:shift+W" flies fast).
bool scriptHolds(const std::vector<ScriptedKey>& keys, int frame, int key);

}  // namespace racer
