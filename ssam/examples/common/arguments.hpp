// SPDX-License-Identifier: MIT
#pragma once
// The examples' command line, keeping the project's command-line contract (game/README.md
// "Command-line contract") without the engine's helper, since the examples build against an
// installed ssam alone: exit 0 done, 1 the work failed, 2 a usage error, each message
// "<tool>: error: ..." on stderr -- and 77 when no OpenGL 3.3 core (or ES 3.0) context can be made, which
// the tests report as skipped.
#include <stdexcept>
#include <string>

namespace gl_example {

inline constexpr int kExitFailure = 1;
inline constexpr int kExitUsage = 2;

// Which example is running: its name (messages, the default --out) and whether it bends its
// foliage in the wind (then it takes --wind).
struct Tool {
    const char* name;
    bool bendsInTheWind = false;
};

// Where a headless context comes from: EGL_EXT_platform_device (NVIDIA's and AMD's headless EGL,
// and Mesa's devices, its software one included) or Mesa's surfaceless platform; Auto tries the
// device platform first, then the surfaceless one.
enum class EglPlatform { Auto, Device, Surfaceless };

// The host's context: OpenGL 3.3 core, or OpenGL ES 3.0 (what WebGL2 is; ssam::gl::Api::Gles30).
enum class ContextApi { Gl, Gles };

struct Arguments {
    bool headless = false;
    EglPlatform egl = EglPlatform::Auto;  // --egl, headless only
    ContextApi api = ContextApi::Gl;      // --api
    std::string out;                      // headless only; default <tool>.png
    std::string mask;                     // headless only; "" = not written
    int frames = 0;                       // window only; 0: until closed
    float wind = 0.0f;                    // --wind (tools that bend in the wind; their default kDefaultWind)
    enum class Mist { None, After, Before } mist = Mist::None;  // --mist: the host's transparent pass
    int repeat = 1;                   // --repeat: headless, time the SSAM frame this many times
    float depthMaskThreshold = 0.0f;  // --depth-threshold: ssam::gl::Settings::depthMaskThreshold
    enum class Precision { Rgba8, Rgba16f, Rg16f } precision = Precision::Rgba8;  // --precision: maskPrecision
    bool help = false;
};

// Parses argv. Throws UsageError for an unknown flag, a missing or malformed value, an --out or
// --mask name that is not .png, or --frames with --headless/--out/--mask (one frame is rendered there).
Arguments parseArguments(const Tool& tool, int argc, char** argv);

// The --help text.
std::string usage(const Tool& tool);

struct UsageError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// "<tool>: error: <message>" on stderr.
void printError(const Tool& tool, const std::string& message);

}  // namespace gl_example
