// SPDX-License-Identifier: MIT
#pragma once
// Numeric image comparison in the convention of OpenImageIO's idiff
// (ImageBufAlgo::compare), so thresholds and reports carry over between the two:
//   - per value: error = |a - b|; a pixel is "over" a threshold when any channel is;
//   - mean and RMS error are over all width*height*channels values;
//   - PSNR = 20 log10(peak / RMS), peak = max(1, largest |value| in either image);
//   - Fail when more than failPercent % of pixels are over failThreshold, or the max
//     error exceeds hardFail; otherwise Warn likewise with the warn settings; else Pass.
//     (This is idiff's documented rule. idiff 2.4's -allowfailures check, default 0,
//     returns PASS early whenever no pixel is over failThreshold, so it never warns in
//     that case; we do, since a warn threshold below the fail threshold is meant to.)
// Non-finite values: NaN vs NaN and Inf vs Inf match; any other pairing with a non-finite
// value makes the max error infinite at that value and counts as over both thresholds
// (idiff skips counting the first one; we count every one). Such values stay out of the
// mean and RMS, as in idiff.
#include <cstddef>
#include <limits>
#include <string>

#include "engine/capture/image.hpp"

namespace engine::capture {

struct CompareOptions {
    float failThreshold = 1e-6f;                         // idiff -fail
    float warnThreshold = 1e-6f;                         // idiff -warn
    float failPercent = 0.0f;                            // idiff -failpercent: % of pixels allowed over failThreshold
    float warnPercent = 0.0f;                            // idiff -warnpercent
    float hardFail = std::numeric_limits<float>::max();  // idiff -hardfail: any error above fails
    float hardWarn = std::numeric_limits<float>::max();  // idiff -hardwarn
};

enum class Verdict { Pass, Warn, Fail };

const char* verdictName(Verdict verdict);  // "PASS", "WARNING", "FAILURE" as idiff prints

struct CompareResult {
    double meanError = 0.0;
    double rmsError = 0.0;
    double psnr = std::numeric_limits<double>::infinity();  // infinite when identical
    double maxError = 0.0;
    int maxX = 0, maxY = 0, maxChannel = 0;  // where maxError occurred (first such value)
    std::size_t pixelCount = 0;
    std::size_t pixelsOverWarn = 0;
    std::size_t pixelsOverFail = 0;
    Verdict verdict = Verdict::Pass;
    // Non-empty when the images could not be compared (different size or channel count);
    // the verdict is then Fail and the statistics are meaningless zeros.
    std::string mismatch;
};

// PSNR in dB: 20 log10(peak / rms); +infinity when rms is 0 (identical images).
// Shared with the benchmark metrics (metrics.hpp), which use peak 1.
double psnrFromRms(double rms, double peak);

// Why two images cannot be compared value by value (size or channel count), or "" when they can.
std::string describeMismatch(const Image& a, const Image& b);

// Never throws for mismatched images: that is a Fail with `mismatch` explaining it.
CompareResult compareImages(const Image& a, const Image& b, const CompareOptions& options = {});

}  // namespace engine::capture
