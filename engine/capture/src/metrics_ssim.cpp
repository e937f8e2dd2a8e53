// SPDX-License-Identifier: MIT
// SSIM (Wang, Bovik, Sheikh, Simoncelli, "Image quality assessment: from error visibility to
// structural similarity", IEEE TIP 2004) on Rec.709 luma of sRGB-encoded colour; see metrics.hpp.
//
//   SSIM(x, y) = (2 mu_x mu_y + C1)(2 sigma_xy + C2) / ((mu_x^2 + mu_y^2 + C1)(sigma_x^2 + sigma_y^2 + C2))
//   C1 = (K1 L)^2, C2 = (K2 L)^2, K1 = 0.01, K2 = 0.03, L = 1,
// with local statistics weighted by an 11x11 Gaussian (sigma 1.5, normalised to sum 1) and the
// map averaged over the window positions that lie wholly inside the image.
#include <array>
#include <cmath>
#include <string>

#include "engine/capture/metrics.hpp"
#include "engine/core/error.hpp"
#include "metrics_support.hpp"

namespace engine::capture {
namespace {

using namespace metrics_detail;

constexpr int kWindow = 11;
constexpr double kSigma = 1.5;
constexpr double kC1 = 0.01 * 0.01;
constexpr double kC2 = 0.03 * 0.03;

std::array<double, kWindow> gaussianWindow() {
    std::array<double, kWindow> w{};
    double sum = 0.0;
    for (int i = 0; i < kWindow; ++i) {
        const int fromCentre = i - kWindow / 2;  // kWindow is odd: the centre tap is 0
        const double x = fromCentre;
        w[static_cast<std::size_t>(i)] = std::exp(-x * x / (2.0 * kSigma * kSigma));
        sum += w[static_cast<std::size_t>(i)];
    }
    for (double& v : w) v /= sum;
    return w;
}

}  // namespace

double ssim(const Image& reference, const Image& test) {
    requireComparable(reference, test, "ssim");
    if (reference.width < kWindow || reference.height < kWindow)
        throw Error("ssim: images are " + std::to_string(reference.width) + "x" + std::to_string(reference.height) +
                    ", smaller than the 11x11 window");
    const std::vector<float> a = srgbLuma(reference, "ssim");
    const std::vector<float> b = srgbLuma(test, "ssim");
    const auto window = gaussianWindow();

    const int width = reference.width, height = reference.height;
    const int outWidth = width - (kWindow - 1), outHeight = height - (kWindow - 1);
    const auto w = static_cast<std::size_t>(width);
    const auto ow = static_cast<std::size_t>(outWidth);

    // Horizontal pass ('valid' positions only) of a, b, a^2, b^2, ab: five planes of outWidth x height.
    // In double: sigma^2 = E[a^2] - mu^2 cancels, and C2 is only 9e-4, so float sums would put
    // errors of ~1e-5 into flat regions.
    constexpr std::size_t kPlanes = 5;
    std::vector<double> rows(kPlanes * ow * static_cast<std::size_t>(height), 0.0f);
    auto plane = [&](std::size_t p, int y) {
        return &rows[(p * static_cast<std::size_t>(height) + static_cast<std::size_t>(y)) * ow];
    };
    forEachRow(height, [&](int y) {
        const float* ra = &a[static_cast<std::size_t>(y) * w];
        const float* rb = &b[static_cast<std::size_t>(y) * w];
        double* ma = plane(0, y);
        double* mb = plane(1, y);
        double* maa = plane(2, y);
        double* mbb = plane(3, y);
        double* mab = plane(4, y);
        for (std::size_t k = 0; k < window.size(); ++k) {
            const double g = window[k];
            for (std::size_t x = 0; x < ow; ++x) {
                const double va = ra[x + k], vb = rb[x + k];
                ma[x] += g * va;
                mb[x] += g * vb;
                maa[x] += g * (va * va);
                mbb[x] += g * (vb * vb);
                mab[x] += g * (va * vb);
            }
        }
    });

    // Vertical pass and the SSIM formula, one output row at a time.
    const double sum = sumRows(outHeight, [&](int y) {
        std::array<std::vector<double>, kPlanes> m;
        for (auto& v : m) v.assign(ow, 0.0);
        for (std::size_t k = 0; k < window.size(); ++k) {
            const double g = window[k];
            for (std::size_t p = 0; p < kPlanes; ++p) {
                const double* in = plane(p, y + static_cast<int>(k));
                double* out = m[p].data();
                for (std::size_t x = 0; x < ow; ++x) out[x] += g * in[x];
            }
        }
        double rowSum = 0.0;
        for (std::size_t x = 0; x < ow; ++x) {
            const double muA = m[0][x], muB = m[1][x];
            const double varA = m[2][x] - muA * muA;
            const double varB = m[3][x] - muB * muB;
            const double cov = m[4][x] - muA * muB;
            rowSum +=
                ((2.0 * muA * muB + kC1) * (2.0 * cov + kC2)) / ((muA * muA + muB * muB + kC1) * (varA + varB + kC2));
        }
        return rowSum;
    });
    return sum / (static_cast<double>(outWidth) * static_cast<double>(outHeight));
}

}  // namespace engine::capture
