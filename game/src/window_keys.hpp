#pragma once
// The window's keys, as pure functions of GLFW key codes so they are unit-tested without a
// window: 1-8 pick a technique (transparency::allTechniques() order), T / Shift+T step to
// the next / previous one, C cycles the camera (chase, pan, free), P pauses the simulation,
// Esc quits. A key script (`racer --script`, hidden: for tests) presses keys at given frames.
#include <string>
#include <vector>

namespace racer {

enum class WindowAction { None, Quit, SelectTechnique, NextTechnique, PreviousTechnique, NextCamera, TogglePause };

struct KeyAction {
    WindowAction action = WindowAction::None;
    int technique = -1;  // SelectTechnique: index into transparency::allTechniques()
};

// `key` is a GLFW_KEY_* code (the top row's digits and the keypad's both select).
KeyAction actionForKey(int key, bool shift);

// The GLFW keys the window polls for presses (every key actionForKey maps to an action).
const std::vector<int>& watchedKeys();

struct ScriptedKey {
    int frame = 0;  // pressed before this frame is rendered (0 = the first frame)
    int key = 0;    // GLFW_KEY_*
    bool shift = false;
};

// "FRAME:KEY,FRAME:KEY..." with KEY one of 1-8, T, C, P, Esc, each optionally "shift+"-
// prefixed, e.g. "2:3,4:C,6:shift+T,9:Esc". Throws engine::Error naming the bad entry.
std::vector<ScriptedKey> parseKeyScript(const std::string& script);

}  // namespace racer
