// SPDX-License-Identifier: MIT
#include "window_keys.hpp"

#include <GLFW/glfw3.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <optional>
#include <string_view>
#include <utility>

#include "engine/core/usage_error.hpp"

namespace racer {

KeyAction actionForKey(int key, bool shift) {
    if (key >= GLFW_KEY_1 && key <= GLFW_KEY_8) return {WindowAction::SelectTechnique, key - GLFW_KEY_1};
    if (key >= GLFW_KEY_KP_1 && key <= GLFW_KEY_KP_8) return {WindowAction::SelectTechnique, key - GLFW_KEY_KP_1};
    switch (key) {
        case GLFW_KEY_T: return {shift ? WindowAction::PreviousTechnique : WindowAction::NextTechnique};
        case GLFW_KEY_C: return {WindowAction::NextCamera};
        case GLFW_KEY_P: return {WindowAction::TogglePause};
        case GLFW_KEY_R: return {WindowAction::Autopilot};
        case GLFW_KEY_H: return {WindowAction::ToggleHud};
        case GLFW_KEY_V: return {WindowAction::ToggleCompare};
        case GLFW_KEY_B: return {WindowAction::NextCompared};
        case GLFW_KEY_ESCAPE: return {WindowAction::Quit};
        default: return {};
    }
}

const std::vector<int>& watchedKeys() {
    static const std::vector<int> keys = [] {
        std::vector<int> k{GLFW_KEY_T, GLFW_KEY_C, GLFW_KEY_P, GLFW_KEY_R,
                           GLFW_KEY_H, GLFW_KEY_V, GLFW_KEY_B, GLFW_KEY_ESCAPE};
        for (int i = 0; i < 8; ++i) {
            k.push_back(GLFW_KEY_1 + i);
            k.push_back(GLFW_KEY_KP_1 + i);
        }
        return k;
    }();
    return keys;
}

HeldDriveKeys driveControls(const std::function<bool(int key)>& held) {
    auto either = [&](int a, int b) { return held(a) || held(b); };
    const bool gas = either(GLFW_KEY_W, GLFW_KEY_UP), brake = either(GLFW_KEY_S, GLFW_KEY_DOWN);
    const bool left = either(GLFW_KEY_A, GLFW_KEY_LEFT), right = either(GLFW_KEY_D, GLFW_KEY_RIGHT);
    HeldDriveKeys k;
    k.controls.throttle = float(gas) - float(brake);
    k.controls.steer = float(left) - float(right);
    k.any = gas || brake || left || right;
    return k;
}

const std::vector<int>& driveKeys() {
    static const std::vector<int> keys{GLFW_KEY_W, GLFW_KEY_UP,   GLFW_KEY_S, GLFW_KEY_DOWN,
                                       GLFW_KEY_A, GLFW_KEY_LEFT, GLFW_KEY_D, GLFW_KEY_RIGHT};
    return keys;
}

const char* driveKeysHelp() { return "W/Up accelerate, S/Down brake/reverse, A/D or Left/Right steer, R autopilot"; }

FlyControls flyControls(const std::function<bool(int key)>& held) {
    auto axis = [&](int negative, int positive) { return float(held(positive)) - float(held(negative)); };
    auto either = [&](int a, int b) { return held(a) || held(b); };
    FlyControls c;
    c.move.x = axis(GLFW_KEY_A, GLFW_KEY_D);
    const bool down = held(GLFW_KEY_Q) || held(GLFW_KEY_LEFT_CONTROL) || held(GLFW_KEY_RIGHT_CONTROL);
    const bool up = held(GLFW_KEY_E) || held(GLFW_KEY_SPACE);
    c.move.y = float(up) - float(down);
    c.move.z = axis(GLFW_KEY_S, GLFW_KEY_W);
    c.turn.x = axis(GLFW_KEY_RIGHT, GLFW_KEY_LEFT);  // positive yaw turns left
    c.turn.y = axis(GLFW_KEY_DOWN, GLFW_KEY_UP);
    c.fast = either(GLFW_KEY_LEFT_SHIFT, GLFW_KEY_RIGHT_SHIFT);
    return c;
}

const std::vector<int>& flyKeys() {
    static const std::vector<int> keys{GLFW_KEY_W,
                                       GLFW_KEY_S,
                                       GLFW_KEY_A,
                                       GLFW_KEY_D,
                                       GLFW_KEY_Q,
                                       GLFW_KEY_E,
                                       GLFW_KEY_SPACE,
                                       GLFW_KEY_LEFT_CONTROL,
                                       GLFW_KEY_RIGHT_CONTROL,
                                       GLFW_KEY_LEFT,
                                       GLFW_KEY_RIGHT,
                                       GLFW_KEY_UP,
                                       GLFW_KEY_DOWN,
                                       GLFW_KEY_LEFT_SHIFT,
                                       GLFW_KEY_RIGHT_SHIFT};
    return keys;
}

const char* flyKeysHelp() {
    return "W/S forward/back, A/D strafe, Q/E or Ctrl/Space down/up, arrows or right mouse drag look, Shift fast";
}

namespace {

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return s;
}

int keyNamed(const std::string& name) {
    if (name.size() == 1 && name[0] >= '1' && name[0] <= '8') return GLFW_KEY_1 + (name[0] - '1');
    if (name == "t") return GLFW_KEY_T;
    if (name == "c") return GLFW_KEY_C;
    if (name == "p") return GLFW_KEY_P;
    if (name == "r") return GLFW_KEY_R;
    if (name == "h") return GLFW_KEY_H;
    if (name == "v") return GLFW_KEY_V;
    if (name == "b") return GLFW_KEY_B;
    if (name == "esc") return GLFW_KEY_ESCAPE;
    static const std::pair<const char*, int> fly[] = {
        {"w", GLFW_KEY_W},       {"a", GLFW_KEY_A},         {"s", GLFW_KEY_S},         {"d", GLFW_KEY_D},
        {"q", GLFW_KEY_Q},       {"e", GLFW_KEY_E},         {"space", GLFW_KEY_SPACE}, {"ctrl", GLFW_KEY_LEFT_CONTROL},
        {"left", GLFW_KEY_LEFT}, {"right", GLFW_KEY_RIGHT}, {"up", GLFW_KEY_UP},       {"down", GLFW_KEY_DOWN}};
    for (const auto& [n, key] : fly)
        if (name == n) return key;
    return -1;
}

// A number that is all of `text`, in lo..hi; nullopt otherwise.
std::optional<int> numberIn(std::string_view text, int lo, int hi) {
    int n = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), n);
    if (ec != std::errc() || end != text.data() + text.size() || n < lo || n > hi) return std::nullopt;
    return n;
}

// "size=WxH" (each side 1..32767, what X11 and Win32 windows can be) or "minimize=MS" into
// `change`; returns why `name` is neither, or null.
const char* readWindowChange(const std::string& name, ScriptedWindowChange& change) {
    const std::string_view text = name;
    const std::size_t equals = text.find('=');
    const std::string_view what = text.substr(0, equals), value = text.substr(equals + 1);
    if (what == "size") {
        const std::size_t x = value.find('x');
        const auto width = numberIn(value.substr(0, x), 1, 32767);
        const auto height = x == std::string_view::npos ? std::nullopt : numberIn(value.substr(x + 1), 1, 32767);
        if (!width || !height) return "the size is not WIDTHxHEIGHT with each side in 1..32767";
        change.width = *width;
        change.height = *height;
        return nullptr;
    }
    if (what == "minimize") {
        const auto ms = numberIn(value, 1, 60000);
        if (!ms) return "the minimised time is not a number of milliseconds in 1..60000";
        change.minimizeMs = *ms;
        return nullptr;
    }
    return "unknown window change (size= or minimize=)";
}

}  // namespace

WindowScript parseWindowScript(const std::string& script) {
    WindowScript parsed;
    std::size_t start = 0;
    while (start <= script.size() && !script.empty()) {
        const std::size_t end = std::min(script.find(',', start), script.size());
        const std::string entry = script.substr(start, end - start);
        const std::size_t colon = entry.find(':');
        auto bad = [&](const char* why) {
            return engine::UsageError(
                "--script entry '" + entry + "': " + why +
                " (expected FRAME:KEY, FIRST-LAST:KEY, FRAME:size=WxH or FRAME:minimize=MS, KEY one "
                "of 1-8 T C P R H V B Esc W A S D Q E Space Ctrl Left Right Up Down, optionally shift+)");
        };
        if (colon == std::string::npos) throw bad("no ':'");
        ScriptedKey k;
        const char* first = entry.data();
        const char* const colonAt = first + colon;
        const auto [ptr, ec] = std::from_chars(first, colonAt, k.frame);
        if (ec != std::errc() || k.frame < 0) throw bad("the frame is not a number >= 0");
        k.lastFrame = k.frame;
        if (ptr != colonAt) {  // FIRST-LAST
            if (*ptr != '-') throw bad("the frame is not a number >= 0");
            const auto [end2, ec2] = std::from_chars(ptr + 1, colonAt, k.lastFrame);
            if (ec2 != std::errc() || end2 != colonAt) throw bad("the last frame is not a number");
            if (k.lastFrame < k.frame) throw bad("the last frame is before the first");
        }
        std::string name = lower(entry.substr(colon + 1));
        if (name.find('=') != std::string::npos) {  // a window change: at one frame, not held
            if (k.lastFrame != k.frame) throw bad("a window change happens at one frame, not over a range");
            ScriptedWindowChange change{k.frame};
            if (const char* why = readWindowChange(name, change)) throw bad(why);
            parsed.changes.push_back(change);
        } else {
            if (name.rfind("shift+", 0) == 0) {
                k.shift = true;
                name = name.substr(6);
            }
            k.key = keyNamed(name);
            if (k.key < 0) throw bad("unknown key");
            parsed.keys.push_back(k);
        }
        start = end + 1;
    }
    auto byFrame = [](const auto& a, const auto& b) { return a.frame < b.frame; };
    std::stable_sort(parsed.keys.begin(), parsed.keys.end(), byFrame);
    std::stable_sort(parsed.changes.begin(), parsed.changes.end(), byFrame);
    return parsed;
}

bool scriptHolds(const std::vector<ScriptedKey>& keys, int frame, int key) {
    const bool shiftKey = key == GLFW_KEY_LEFT_SHIFT;
    return std::any_of(keys.begin(), keys.end(), [&](const ScriptedKey& k) {
        return frame >= k.frame && frame <= k.lastFrame && (k.key == key || (shiftKey && k.shift));
    });
}

}  // namespace racer
