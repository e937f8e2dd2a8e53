// SPDX-License-Identifier: MIT
// Fuzz target: the text parsers of racer's command line — the window script (`--script`,
// racer::parseWindowScript) and --size, --camera and --technique — all run on the same
// input string, cut at its first NUL as argv would be. Seeds: tests/fuzz/corpus/racer_flags.
#include <GLFW/glfw3.h>

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>

#include "engine/core/error.hpp"
#include "fuzz_support.hpp"
#include "racer_options.hpp"
#include "window_keys.hpp"

namespace {

template <typename Parse>
void tryParser(const char* refusalPrefix, Parse parse) {
    try {
        parse();
    } catch (const engine::Error& e) {
        ssam::fuzz::requireMessageNames(e, refusalPrefix);
    }
}

void checkScript(const racer::WindowScript& script) {
    using ssam::fuzz::require;
    for (std::size_t i = 0; i < script.keys.size(); ++i) {
        const racer::ScriptedKey& k = script.keys[i];
        require(k.frame >= 0 && k.lastFrame >= k.frame, "--script key " + std::to_string(i) + ": frames " +
                                                            std::to_string(k.frame) + "-" +
                                                            std::to_string(k.lastFrame));
        require(i == 0 || script.keys[i - 1].frame <= k.frame, "--script keys are not sorted by frame");
        require(k.key >= GLFW_KEY_SPACE && k.key <= GLFW_KEY_LAST, "--script key code " + std::to_string(k.key));
        // The window asks the script about every frame it renders; the answer must not depend
        // on anything but the script (no overflow at the ends of the range).
        require(racer::scriptHolds(script.keys, k.frame, k.key) && racer::scriptHolds(script.keys, k.lastFrame, k.key),
                "--script key " + std::to_string(i) + " is not held over its own frames");
    }
    for (std::size_t i = 0; i < script.changes.size(); ++i) {
        const racer::ScriptedWindowChange& c = script.changes[i];
        require(c.frame >= 0, "--script window change at a negative frame");
        require(i == 0 || script.changes[i - 1].frame <= c.frame, "--script window changes are not sorted by frame");
        const bool resize = c.width >= 1 && c.width <= 32767 && c.height >= 1 && c.height <= 32767 && c.minimizeMs == 0;
        const bool minimize = c.width == 0 && c.height == 0 && c.minimizeMs >= 1 && c.minimizeMs <= 60000;
        require(resize != minimize,
                "--script window change " + std::to_string(i) + " is neither a resize nor a minimise");
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    // A command-line argument ends at its first NUL byte (argv holds C strings).
    const std::string text(reinterpret_cast<const char*>(data), ::strnlen(reinterpret_cast<const char*>(data), size));
    tryParser("--script entry '", [&] { checkScript(racer::parseWindowScript(text)); });
    tryParser("--size '", [&] {
        const racer::FrameSize s = racer::parseFrameSize(text);
        ssam::fuzz::require(s.width >= 1 && s.width <= 16384 && s.height >= 1 && s.height <= 16384,
                            "--size accepted " + std::to_string(s.width) + "x" + std::to_string(s.height));
    });
    tryParser("--camera '", [&] { racer::cameraName(racer::parseCamera(text)); });
    tryParser("--technique '", [&] { racer::parseTechniqueName(text); });
    return 0;
}
