#include "window_keys.hpp"

#include <GLFW/glfw3.h>

#include <algorithm>
#include <cctype>
#include <charconv>

#include "engine/core/error.hpp"

namespace racer {

KeyAction actionForKey(int key, bool shift) {
    if (key >= GLFW_KEY_1 && key <= GLFW_KEY_8) return {WindowAction::SelectTechnique, key - GLFW_KEY_1};
    if (key >= GLFW_KEY_KP_1 && key <= GLFW_KEY_KP_8) return {WindowAction::SelectTechnique, key - GLFW_KEY_KP_1};
    switch (key) {
        case GLFW_KEY_T: return {shift ? WindowAction::PreviousTechnique : WindowAction::NextTechnique};
        case GLFW_KEY_C: return {WindowAction::NextCamera};
        case GLFW_KEY_P: return {WindowAction::TogglePause};
        case GLFW_KEY_ESCAPE: return {WindowAction::Quit};
        default: return {};
    }
}

const std::vector<int>& watchedKeys() {
    static const std::vector<int> keys = [] {
        std::vector<int> k{GLFW_KEY_T, GLFW_KEY_C, GLFW_KEY_P, GLFW_KEY_ESCAPE};
        for (int i = 0; i < 8; ++i) {
            k.push_back(GLFW_KEY_1 + i);
            k.push_back(GLFW_KEY_KP_1 + i);
        }
        return k;
    }();
    return keys;
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
    if (name == "esc") return GLFW_KEY_ESCAPE;
    return -1;
}

}  // namespace

std::vector<ScriptedKey> parseKeyScript(const std::string& script) {
    std::vector<ScriptedKey> keys;
    std::size_t start = 0;
    while (start <= script.size() && !script.empty()) {
        const std::size_t end = std::min(script.find(',', start), script.size());
        const std::string entry = script.substr(start, end - start);
        const std::size_t colon = entry.find(':');
        auto bad = [&](const char* why) {
            return engine::Error("--script entry '" + entry + "': " + why + " (expected FRAME:KEY, KEY one of 1-8 T C P Esc, "
                                 "optionally shift+)");
        };
        if (colon == std::string::npos) throw bad("no ':'");
        ScriptedKey k;
        const char* first = entry.data();
        const auto [ptr, ec] = std::from_chars(first, first + colon, k.frame);
        if (ec != std::errc() || ptr != first + colon || k.frame < 0) throw bad("the frame is not a number >= 0");
        std::string name = lower(entry.substr(colon + 1));
        if (name.rfind("shift+", 0) == 0) {
            k.shift = true;
            name = name.substr(6);
        }
        k.key = keyNamed(name);
        if (k.key < 0) throw bad("unknown key");
        keys.push_back(k);
        start = end + 1;
    }
    std::stable_sort(keys.begin(), keys.end(), [](const ScriptedKey& a, const ScriptedKey& b) { return a.frame < b.frame; });
    return keys;
}

}  // namespace racer
