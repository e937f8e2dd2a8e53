// SPDX-License-Identifier: MIT
#include "arguments.hpp"

#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

namespace gl_embedding {

namespace {

int parseFrames(const std::string& text) {
    char* end = nullptr;
    errno = 0;
    const long n = std::strtol(text.c_str(), &end, 10);
    if (text.empty() || *end != '\0' || errno == ERANGE || n < 1 || n > 1000000)
        throw UsageError("--frames '" + text + "': expected a whole number of frames in 1..1000000");
    return static_cast<int>(n);
}

}  // namespace

Arguments parseArguments(int argc, char** argv) {
    Arguments args;
    bool outGiven = false, framesGiven = false;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        auto value = [&]() -> std::string {
            if (i + 1 >= argc) throw UsageError(arg + " needs a value");
            return argv[++i];
        };
        if (arg == "--help" || arg == "-h") args.help = true;
        else if (arg == "--headless") args.headless = true;
        else if (arg == "--out") args.out = value(), args.headless = true, outGiven = true;
        else if (arg == "--frames") args.frames = parseFrames(value()), framesGiven = true;
        else throw UsageError("unknown argument '" + arg + "' (see --help)");
    }
    if (framesGiven && args.headless)
        throw UsageError(std::string("--frames counts window frames; ") + (outGiven ? "--out" : "--headless") +
                         " renders one frame");
    std::string extension = std::filesystem::path(args.out).extension().string();
    for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (extension != ".png") throw UsageError("--out '" + args.out + "': the name must end in .png");
    return args;
}

std::string usage() {
    return std::string("usage: ") + kToolName +
           " [--headless] [--out PATH.png] [--frames N]\n"
           "  --headless    render one frame offscreen (EGL surfaceless) and write it (the default without a display)\n"
           "  --out PATH    the PNG to write (implies --headless; default ssam_gl_embedding.png); its directory\n"
           "                must exist, and is checked before rendering\n"
           "  --frames N    in a window: close after N frames (default: when the window is closed)\n"
           "Exit status: 0 done, 1 the work failed, 2 usage error, 77 no OpenGL 3.3 core context; messages are\n"
           "'ssam_gl_embedding: error: ...' on stderr.\n";
}

void printError(const std::string& message) { std::fprintf(stderr, "%s: error: %s\n", kToolName, message.c_str()); }

}  // namespace gl_embedding
