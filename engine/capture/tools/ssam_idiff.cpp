// SPDX-License-Identifier: MIT
// ssam-idiff: compare two images the way OpenImageIO's idiff does, with our reader.
//
//   ssam-idiff A B [--fail F] [--warn W] [--failpercent P] [--warnpercent P]
//                  [--hardfail H] [--hardwarn H] [--diff out.png|out.exr] [--scale S] [--linear]
//
// Exit status, as idiff's: 0 PASS, 1 WARNING, 2 FAILURE (including a size or channel-count
// mismatch), 4 an input could not be read or the diff image not written (idiff's ErrFile).
// The project's command-line contract (engine/cli/command_line.hpp) holds otherwise: a usage
// mistake (unknown flag, bad value, a --diff name with no writer) exits 2 -- shared with
// FAILURE, as idiff's own usage errors are not 0 or 1 either: "not shown to match" -- and
// every message is "ssam-idiff: error: ..." on stderr. The --diff place is proven writable
// before the inputs are read, and the diff image is written whole or not at all.
//
// Statistics are always printed (idiff prints them only on failure or with -v).
// By default values are compared as stored (8-bit codes / 255, like idiff) so thresholds
// mean the same as idiff's; --linear compares linear light instead. One difference from
// idiff stays on purpose: PNG/TGA colour is compared straight, not premultiplied, so a
// colour change under alpha 0 is still seen.
#include <CLI/CLI.hpp>

#include <charconv>
#include <cstdio>
#include <iostream>
#include <sstream>
#include <string>

#include "engine/capture/compare.hpp"
#include "engine/capture/diff_image.hpp"
#include "engine/capture/image_read.hpp"
#include "engine/capture/metrics.hpp"
#include "engine/cli/command_line.hpp"
#include "engine/capture/image_write.hpp"
#include "engine/core/error.hpp"
#include "engine/core/output_file.hpp"
#include "engine/core/usage_error.hpp"

namespace {

using namespace engine::capture;

constexpr int kExitFileError = 4;

int exitCode(Verdict verdict) {
    switch (verdict) {
        case Verdict::Pass: return 0;
        case Verdict::Warn: return 1;
        case Verdict::Fail: return 2;
    }
    return 2;
}

// idiff prints doubles with iostream's default precision and "inf"/"nan" spelled out.
std::string number(double value) {
    std::ostringstream out;
    out << value;
    return out.str();
}

// Pixel values as idiff prints them: the shortest text that reads back as the same float.
std::string shortest(float value) {
    char text[32];
    const auto end = std::to_chars(text, text + sizeof text, value).ptr;
    return std::string(text, end);
}

std::string percentOf(std::size_t count, std::size_t total) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g",
                  total ? 100.0 * static_cast<double>(count) / static_cast<double>(total) : 0.0);
    return text;
}

void printReport(const Image& a, const Image& b, const CompareResult& r, const CompareOptions& options) {
    std::cout << "  Mean error = " << number(r.meanError) << "\n"
              << "  RMS error = " << number(r.rmsError) << "\n"
              << "  Peak SNR = " << number(r.psnr) << "\n"
              << "  Max error  = " << number(r.maxError);
    if (r.maxError != 0.0) {
        std::cout << " @ (" << r.maxX << ", " << r.maxY << ", "
                  << a.channelNames[static_cast<std::size_t>(r.maxChannel)] << ")  values are ";
        for (int c = 0; c < a.channels; ++c) std::cout << (c ? ", " : "") << shortest(a.at(r.maxX, r.maxY, c));
        std::cout << " vs ";
        for (int c = 0; c < b.channels; ++c) std::cout << (c ? ", " : "") << shortest(b.at(r.maxX, r.maxY, c));
    }
    std::cout << "\n"
              << "  " << r.pixelsOverWarn << " pixels (" << percentOf(r.pixelsOverWarn, r.pixelCount) << "%) over "
              << options.warnThreshold << "\n"
              << "  " << r.pixelsOverFail << " pixels (" << percentOf(r.pixelsOverFail, r.pixelCount) << "%) over "
              << options.failThreshold << "\n";
}

struct Arguments {
    std::string pathA, pathB, diffPath;
    CompareOptions options;
    float scale = 1.0f;
    bool linear = false;
    bool metrics = false;
};

int compare(const Arguments& args) {
    if (!args.diffPath.empty()) {
        try {
            requireImageExtension(args.diffPath);
        } catch (const engine::Error& e) {
            throw engine::UsageError(std::string("--diff: ") + e.what());
        }
    }
    try {
        if (!args.diffPath.empty()) engine::requireWritableFile(args.diffPath, /*createDirectory=*/false);
        ReadOptions readOptions;
        readOptions.linearize = args.linear;
        const Image a = readImage(args.pathA, readOptions);
        const Image b = readImage(args.pathB, readOptions);

        std::cout << "Comparing \"" << args.pathA << "\" and \"" << args.pathB << "\"\n";
        const CompareResult result = compareImages(a, b, args.options);
        if (!result.mismatch.empty()) {
            std::cout << "  " << result.mismatch << "\n" << verdictName(result.verdict) << "\n";
            return exitCode(result.verdict);
        }
        printReport(a, b, result, args.options);
        if (args.metrics) {
            // The bench's measures of B against A, on linear light whatever --linear says.
            ReadOptions linear;
            linear.linearize = true;
            const Image la = readImage(args.pathA, linear), lb = readImage(args.pathB, linear);
            std::printf("  FLIP %.4f  RMSE (linear) %.5f\n", engine::capture::flip(la, lb),
                        engine::capture::rmseLinear(la, lb));
        }
        if (!args.diffPath.empty()) writeDiffImage(args.diffPath, a, b, args.scale);
        std::cout << verdictName(result.verdict) << "\n";
        return exitCode(result.verdict);
    } catch (const engine::Error& e) {
        engine::cli::printError("ssam-idiff", e.what());
        return kExitFileError;
    }
}

}  // namespace

// Only declaring the options runs outside runTool's handler: an exception there is a bug of the
// tool itself (a flag declared twice), which the tool's --help test finds first.
int main(int argc, char** argv) {  // NOLINT(bugprone-exception-escape)
    CLI::App app{
        "Compare two images like OpenImageIO's idiff. Exit 0 pass, 1 warn, 2 fail (or a usage error), 4 an "
        "input unreadable or the diff image not written."};
    Arguments args;
    CompareOptions& options = args.options;
    app.add_option("A", args.pathA, "First image")->required();
    app.add_option("B", args.pathB, "Second image")->required();
    app.add_option("--fail", options.failThreshold, "Failure threshold: per-channel absolute difference")
        ->capture_default_str();
    app.add_option("--warn", options.warnThreshold, "Warning threshold: per-channel absolute difference")
        ->capture_default_str();
    app.add_option("--failpercent", options.failPercent, "Percentage of pixels allowed over --fail")
        ->capture_default_str();
    app.add_option("--warnpercent", options.warnPercent, "Percentage of pixels allowed over --warn")
        ->capture_default_str();
    app.add_option("--hardfail", options.hardFail, "Fail if any one value differs by more than this");
    app.add_option("--hardwarn", options.hardWarn, "Warn if any one value differs by more than this");
    app.add_option("--diff", args.diffPath, "Write |A-B| * scale to this .png or .exr");
    app.add_option("--scale", args.scale, "Scale factor for the difference image")->capture_default_str();
    app.add_flag("--linear", args.linear, "Compare in linear light (decode sRGB) instead of stored values");
    app.add_flag("--metrics", args.metrics,
                 "Also print B's mean FLIP and linear RMSE against A (engine/capture/metrics.hpp), as ssam-bench "
                 "measures its frames");
    app.footer(
        "Why not idiff itself: the golden tests need three things it does not do.\n"
        "  - PNG colour is compared straight, not premultiplied: idiff premultiplies on reading,\n"
        "    so a colour change under alpha 0 would pass unseen.\n"
        "  - A warning threshold below the fail threshold warns even when no pixel fails (idiff 2.4\n"
        "    returns PASS early), and every non-finite value is counted (idiff skips the first).\n"
        "  - Images are read as the tests and racer read them (engine/capture), --linear compares\n"
        "    linear light, and the statistics are always printed, not only on failure.\n"
        "Otherwise it is idiff: thresholds and numbers carry over between the two.\n"
        "Messages are 'ssam-idiff: error: ...' on stderr; a usage error exits 2.");
    return engine::cli::runTool("ssam-idiff", app, argc, argv, [&] { return compare(args); });
}
