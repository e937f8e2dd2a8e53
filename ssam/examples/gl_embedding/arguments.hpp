// SPDX-License-Identifier: MIT
#pragma once
// The example's command line, keeping the project's command-line contract (game/README.md
// "Command-line contract") without the engine's helper, since the example builds against an
// installed ssam alone: exit 0 done, 1 the work failed, 2 a usage error, each message
// "ssam_gl_embedding: error: ..." on stderr -- and 77 when no OpenGL 3.3 core context can be
// made, which the tests report as skipped.
#include <stdexcept>
#include <string>

namespace gl_embedding {

inline constexpr const char* kToolName = "ssam_gl_embedding";
inline constexpr int kExitFailure = 1;
inline constexpr int kExitUsage = 2;

struct Arguments {
    bool headless = false;
    std::string out = "ssam_gl_embedding.png";  // headless only
    int frames = 0;                             // window only; 0: until closed
    bool help = false;
};

// Parses argv. Throws UsageError for an unknown flag, a missing or malformed value, an --out
// name that is not .png, or --frames with --headless/--out (one frame is rendered there).
Arguments parseArguments(int argc, char** argv);

// The --help text.
std::string usage();

struct UsageError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// "ssam_gl_embedding: error: <message>" on stderr.
void printError(const std::string& message);

}  // namespace gl_embedding
