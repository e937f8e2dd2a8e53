// SPDX-License-Identifier: MIT
#include "engine/capture/compare.hpp"

#include <algorithm>
#include <cmath>

namespace engine::capture {
namespace {

std::string sizeText(const Image& image) {
    return std::to_string(image.width) + "x" + std::to_string(image.height) + "x" + std::to_string(image.channels);
}

}  // namespace

std::string describeMismatch(const Image& a, const Image& b) {
    if (a.width == b.width && a.height == b.height && a.channels == b.channels) return {};
    return "images differ in size: " + sizeText(a) + " vs " + sizeText(b) + " (width x height x channels)";
}

double psnrFromRms(double rms, double peak) { return 20.0 * std::log10(peak / rms); }

const char* verdictName(Verdict verdict) {
    switch (verdict) {
        case Verdict::Pass: return "PASS";
        case Verdict::Warn: return "WARNING";
        case Verdict::Fail: return "FAILURE";
    }
    return "?";
}

CompareResult compareImages(const Image& a, const Image& b, const CompareOptions& options) {
    CompareResult result;
    result.mismatch = describeMismatch(a, b);
    if (!result.mismatch.empty()) {
        result.verdict = Verdict::Fail;
        result.psnr = 0.0;
        return result;
    }
    result.pixelCount = a.pixelCount();
    const auto channels = static_cast<std::size_t>(a.channels);

    // idiff's PSNR peak: 1 for normalised images, the largest magnitude seen for HDR ones.
    double peak = 1.0;
    double sumError = 0.0;
    double sumSquaredError = 0.0;
    auto recordMax = [&](double error, std::size_t pixel, std::size_t c) {
        result.maxError = error;
        result.maxX = static_cast<int>(pixel % static_cast<std::size_t>(a.width));
        result.maxY = static_cast<int>(pixel / static_cast<std::size_t>(a.width));
        result.maxChannel = static_cast<int>(c);
    };

    for (std::size_t p = 0; p < result.pixelCount; ++p) {
        bool overWarn = false, overFail = false;
        for (std::size_t c = 0; c < channels; ++c) {
            const double va = a.pixels[p * channels + c];
            const double vb = b.pixels[p * channels + c];
            if (!std::isfinite(va) || !std::isfinite(vb)) {
                if (std::isnan(va) == std::isnan(vb) && std::isinf(va) == std::isinf(vb)) continue;
                if (std::isfinite(result.maxError)) recordMax(std::numeric_limits<double>::infinity(), p, c);
                overWarn = overFail = true;
                continue;
            }
            const double error = std::abs(va - vb);
            peak = std::max({peak, std::abs(va), std::abs(vb)});
            sumError += error;
            sumSquaredError += error * error;
            if (error > result.maxError) recordMax(error, p, c);
            overWarn = overWarn || error > options.warnThreshold;
            overFail = overFail || error > options.failThreshold;
        }
        result.pixelsOverWarn += overWarn ? 1 : 0;
        result.pixelsOverFail += overFail ? 1 : 0;
    }

    const auto values = static_cast<double>(result.pixelCount * channels);
    result.meanError = sumError / values;
    result.rmsError = std::sqrt(sumSquaredError / values);
    result.psnr = psnrFromRms(result.rmsError, peak);  // +inf when identical, as idiff

    const auto pixels = static_cast<double>(result.pixelCount);
    if (static_cast<double>(result.pixelsOverFail) > options.failPercent / 100.0 * pixels ||
        result.maxError > options.hardFail)
        result.verdict = Verdict::Fail;
    else if (static_cast<double>(result.pixelsOverWarn) > options.warnPercent / 100.0 * pixels ||
             result.maxError > options.hardWarn)
        result.verdict = Verdict::Warn;
    return result;
}

}  // namespace engine::capture
