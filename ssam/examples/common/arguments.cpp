// SPDX-License-Identifier: MIT
#include "arguments.hpp"

#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <type_traits>

#include "scene.hpp"

namespace gl_example {

namespace {

// All of `text` as a number in [lowest, highest] (strtol / strtof, no overflow, not NaN), else
// UsageError "<flag> '<text>': expected <expected>".
template <class Number>
Number parseNumber(const char* flag, const std::string& text, Number lowest, Number highest, const char* expected) {
    char* end = nullptr;
    errno = 0;
    Number n;
    if constexpr (std::is_floating_point_v<Number>) n = std::strtof(text.c_str(), &end);
    else n = std::strtol(text.c_str(), &end, 10);
    if (text.empty() || *end != '\0' || errno == ERANGE || !(n >= lowest && n <= highest))
        throw UsageError(std::string(flag) + " '" + text + "': expected " + expected);
    return n;
}

Arguments::Mist parseMist(const std::string& text) {
    if (text == "after") return Arguments::Mist::After;
    if (text == "before") return Arguments::Mist::Before;
    throw UsageError("--mist '" + text + "': expected after or before");
}

Arguments::Precision parsePrecision(const std::string& text) {
    if (text == "rgba8") return Arguments::Precision::Rgba8;
    if (text == "rgba16f") return Arguments::Precision::Rgba16f;
    if (text == "rg16f") return Arguments::Precision::Rg16f;
    throw UsageError("--precision '" + text + "': expected rgba8, rgba16f or rg16f");
}

EglPlatform parseEgl(const std::string& text) {
    if (text == "auto") return EglPlatform::Auto;
    if (text == "device") return EglPlatform::Device;
    if (text == "surfaceless") return EglPlatform::Surfaceless;
    throw UsageError("--egl '" + text + "': expected auto, device or surfaceless");
}

ContextApi parseApi(const std::string& text) {
    if (text == "gl") return ContextApi::Gl;
    if (text == "gles") return ContextApi::Gles;
    throw UsageError("--api '" + text + "': expected gl or gles");
}

void requirePng(const char* flag, const std::string& path) {
    std::string extension = std::filesystem::path(path).extension().string();
    for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (extension != ".png") throw UsageError(std::string(flag) + " '" + path + "': the name must end in .png");
}

}  // namespace

Arguments parseArguments(const Tool& tool, int argc, char** argv) {
    Arguments args;
    args.out = std::string(tool.name) + ".png";
    args.wind = tool.bendsInTheWind ? kDefaultWind : 0.0f;
    const char* headlessFlag = nullptr;
    bool framesGiven = false;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        auto value = [&]() -> std::string {
            if (i + 1 >= argc) throw UsageError(arg + " needs a value");
            return argv[++i];
        };
        if (arg == "--help" || arg == "-h") args.help = true;
        else if (arg == "--headless") args.headless = true, headlessFlag = headlessFlag ? headlessFlag : "--headless";
        else if (arg == "--out") args.out = value(), args.headless = true, headlessFlag = "--out";
        else if (arg == "--mask") args.mask = value(), args.headless = true, headlessFlag = "--mask";
        else if (arg == "--egl") args.egl = parseEgl(value()), args.headless = true, headlessFlag = "--egl";
        else if (arg == "--api") args.api = parseApi(value());
        else if (arg == "--mist") args.mist = parseMist(value());
        else if (arg == "--repeat")
            args.repeat = int(parseNumber<long>("--repeat", value(), 1, 100000, "a whole number in 1..100000")),
            args.headless = true;
        else if (arg == "--depth-threshold")
            args.depthMaskThreshold = parseNumber("--depth-threshold", value(), 0.0f, 1.0f, "a mask value in 0..1");
        else if (arg == "--precision") args.precision = parsePrecision(value());
        else if (arg == "--frames")
            args.frames =
                int(parseNumber<long>("--frames", value(), 1, 1000000, "a whole number of frames in 1..1000000")),
            framesGiven = true;
        else if (arg == "--wind" && tool.bendsInTheWind)
            args.wind =
                parseNumber("--wind", value(), -1.0f, 1.0f, "an amplitude in -1..1 (world units at a card's top)");
        else throw UsageError("unknown argument '" + arg + "' (see --help)");
    }
    if (framesGiven && args.headless)
        throw UsageError(std::string("--frames counts window frames; ") + headlessFlag + " renders one frame");
    requirePng("--out", args.out);
    if (!args.mask.empty()) requirePng("--mask", args.mask);
    return args;
}

std::string usage(const Tool& tool) {
    const std::string name = tool.name;
    return "usage: " + name + " [--headless] [--out PATH.png] [--mask PATH.png]" +
           (tool.bendsInTheWind ? " [--wind AMPLITUDE]" : "") +
           " [--mist after|before] [--depth-threshold T] [--precision P] [--repeat N] [--egl PLATFORM]"
           " [--api gl|gles] [--frames N]\n"
           "  --headless    render one frame offscreen (EGL, no window) and write it (the default without a display)\n"
           "  --egl P       the headless context's EGL platform: device (EGL_EXT_platform_device: NVIDIA's and\n"
           "                AMD's headless EGL, Mesa's devices), surfaceless (Mesa), or auto (default: device,\n"
           "                then surfaceless); implies --headless\n"
           "  --api A       the host's context: gl (OpenGL 3.3 core, default) or gles (OpenGL ES 3.0, what\n"
           "                WebGL2 is: ssam::gl::Api::Gles30, the host's shaders as GLSL ES 3.00)\n"
           "  --out PATH    the PNG to write (implies --headless; default " +
           name +
           ".png); its directory\n"
           "                must exist, and is checked before rendering\n"
           "  --mask PATH   also write SSAM's mask as a PNG: red = MAX of the layers' alphas, alpha = their\n"
           "                SUM ([Hathaway 2010] §3.5.2; implies --headless)\n" +
           (tool.bendsInTheWind
                ? "  --wind A      the wind's bend in the host's vertex shader: a card's top moves A world units in x\n"
                  "                (default 0.3; 0 draws exactly what SSAM's built-in programs draw)\n"
                : "") +
           "  --mist WHEN   the host's transparent pass, pale mist behind every card: after SSAM (where later\n"
           "                passes go: they see the foliage depth) or before it (exact here, the mist being\n"
           "                behind all the foliage)\n"
           "  --depth-threshold T  keep the foliage depth only where SSAM's mask reaches T (default 0: wherever\n"
           "                the colour pass wrote it, as the paper); above 0 the mist meets leaf edges without\n"
           "                a dark rim\n"
           "  --precision P SSAM's mask storage: rgba8 (default, the paper's), rgba16f or rg16f (two R16F targets)\n"
           "  --repeat N    headless: draw the frame N times and print the median time of SSAM's passes\n"
           "                (glFinish before and after; implies --headless)\n"
           "  --frames N    in a window: close after N frames (default: when the window is closed)\n"
           "Exit status: 0 done, 1 the work failed, 2 usage error, 77 no OpenGL 3.3 (--api gles: ES 3.0)\n"
           "context; messages are\n"
           "'" +
           name + ": error: ...' on stderr.\n";
}

void printError(const Tool& tool, const std::string& message) {
    std::fprintf(stderr, "%s: error: %s\n", tool.name, message.c_str());
}

}  // namespace gl_example
