// SPDX-License-Identifier: MIT
// LDR-ꟻLIP: P. Andersson, J. Nilsson, T. Akenine-Möller, M. Oskarsson, K. Åström, M. D. Fairchild,
// "ꟻLIP: A Difference Evaluator for Alternating Images", Proc. ACM Comput. Graph. Interact. Tech.
// (HPG) 3(2), 2020. Written from the paper's description; no code from the reference
// implementation was used.
//
// Pipeline (per pixel, reference r and test t, colour clamped to [0,1] linear RGB first):
//
//  Colour pipeline (paper Sec. 4.1)
//   1. linear sRGB -> CIE XYZ (IEC 61966-2-1 D65 matrix) -> YyCxCz, the linearised L*a*b*
//      of Flohr et al.:  Yy = 116 Y/Yn - 16,  Cx = 500 (X/Xn - Y/Yn),  Cz = 200 (Y/Yn - Z/Zn);
//      white (Xn, Yn, Zn) = XYZ of linear RGB (1, 1, 1).
//   2. Each channel is filtered with its contrast sensitivity function, given in the frequency
//      domain as a sum of Gaussians  S(f) = a1 exp(-b1 f^2) + a2 exp(-b2 f^2)  and applied
//      in the spatial domain as  s(x) = a1 sqrt(pi/b1) exp(-pi^2 x^2/b1) + a2 sqrt(pi/b2) exp(-pi^2 x^2/b2),
//      x in degrees (= pixels / PPD), r^2 = x^2 + y^2 for the 2-D kernel:
//         achromatic (Yy): a1 = 1,    b1 = 0.0047, a2 = 0,    b2 = 1e-5
//         red-green  (Cx): a1 = 1,    b1 = 0.0053, a2 = 0,    b2 = 1e-5
//         blue-yellow(Cz): a1 = 34.1, b1 = 0.04,   a2 = 13.5, b2 = 0.025
//      Square kernel of radius ceil(3 sqrt(b_max / (2 pi^2)) PPD) pixels, b_max = 0.04 (three
//      standard deviations of the widest Gaussian; 10 pixels at 67 PPD), the same for all
//      three channels, each kernel normalised to sum 1 over that square. (Taps of the narrow
//      Yy and Cx Gaussians below 1e-9 of their peak, beyond 6 pixels at 67 PPD, are then
//      skipped: they cannot change a float result.)
//   3. Filtered YyCxCz -> XYZ -> linear RGB, clamped to [0,1] (filtering leaves the gamut),
//      -> CIE L*a*b* (same white).
//   4. Hunt adjustment: a* <- 0.01 L* a*,  b* <- 0.01 L* b*.
//   5. HyAB distance: dE = |L*_r - L*_t| + sqrt((a*_r - a*_t)^2 + (b*_r - b*_t)^2).
//   6. dE' = dE^qc, qc = 0.7, normalised by cmax = HyAB(Hunt(green), Hunt(blue))^qc (green
//      = (0,1,0), blue = (0,0,1) linear RGB: the most distant pair) and remapped so small
//      errors get most of [0,1]: with pc = 0.4, pt = 0.95,
//         dEc = pt dE' / (pc cmax)                                 if dE' < pc cmax
//         dEc = pt + (dE' - pc cmax) / (cmax - pc cmax) (1 - pt)    otherwise.
//
//  Feature pipeline (paper Sec. 4.2), on the achromatic channel of the unfiltered image,
//  normalised to [0,1]: (Yy + 16) / 116 = Y / Yn.
//   7. Edges: first derivative of a Gaussian, points: second derivative, sigma = w PPD / 2
//      with w = 0.082 degrees, radius ceil(3 sigma) (9 pixels at 67 PPD). The 2-D kernels
//      are separable: G'(x) G(y) and G(x) G'(y) for edges, G''(x) G(y) and G(x) G''(y) for
//      points. G is normalised to sum 1; G' and G'' have their positive weights normalised
//      to sum 1 and their negative weights to sum -1 (which makes the 2-D kernels normalised
//      the same way). Edge and point strengths are the magnitudes |(fx, fy)|.
//   8. dEf = ( max(| |edge_r| - |edge_t| |, | |point_r| - |point_t| |) / sqrt(2) )^qf, qf = 0.5.
//
//  Combination: dE = dEc^(1 - dEf), in [0,1]; the reported value is its mean over pixels.
//
// Choices and departures, stated plainly:
//   - Pixels per degree default to 0.7 m * (3840 px / 0.7 m) * pi / 180 = 67.02 (the paper's
//     setup); FlipOptions::pixelsPerDegree changes it.
//   - Borders: every filter clamps to the edge pixel (replicate padding).
//   - The CSF kernels use the paper's 1-D amplitude factors a sqrt(pi/b) in the 2-D kernel
//     before normalisation (only the BY channel, a sum of two Gaussians, depends on this).
//   - The second-derivative kernel is normalised directly (positive part to 1, negative part
//     to -1) without first removing its mean; the reference implementation may differ in
//     such normalisation details.
//   - Arithmetic is float per pixel (the mean is summed in double, row by row); results are
//     not meant to match another implementation bit for bit. No cross-check against the
//     reference implementation was run: the constants above are the paper's, and the unit
//     tests check flat-image cases against hand computation from its equations.
//   - The remapped colour error is capped at 1 (a no-op when green-blue is the largest
//     distance in the gamut, as the paper states).
//   - Symmetry: every step treats the two images alike, so flip(a, b) == flip(b, a) exactly.
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string>

#include "engine/capture/metrics.hpp"
#include "engine/core/error.hpp"
#include "metrics_support.hpp"

namespace engine::capture {
namespace {

using namespace metrics_detail;
using Mat3 = std::array<std::array<double, 3>, 3>;

// Paper constants.
constexpr double kQc = 0.7;
constexpr double kPc = 0.4;
constexpr double kPt = 0.95;
constexpr double kQf = 0.5;  // applied as sqrt below
static_assert(kQf == 0.5);
constexpr double kFeatureWidthDegrees = 0.082;

struct Csf {
    double a1, b1, a2, b2;
};
constexpr Csf kCsfAchromatic{1.0, 0.0047, 0.0, 1e-5};
constexpr Csf kCsfRedGreen{1.0, 0.0053, 0.0, 1e-5};
constexpr Csf kCsfBlueYellow{34.1, 0.04, 13.5, 0.025};
constexpr double kCsfWidestB = 0.04;

// IEC 61966-2-1 linear sRGB -> XYZ (D65).
constexpr Mat3 kRgbToXyz{
    {{0.4124564, 0.3575761, 0.1804375}, {0.2126729, 0.7151522, 0.0721750}, {0.0193339, 0.1191920, 0.9503041}}};

Mat3 inverse(const Mat3& m) {
    const double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                       m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                       m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    Mat3 r{};
    r[0][0] = (m[1][1] * m[2][2] - m[1][2] * m[2][1]) / det;
    r[0][1] = (m[0][2] * m[2][1] - m[0][1] * m[2][2]) / det;
    r[0][2] = (m[0][1] * m[1][2] - m[0][2] * m[1][1]) / det;
    r[1][0] = (m[1][2] * m[2][0] - m[1][0] * m[2][2]) / det;
    r[1][1] = (m[0][0] * m[2][2] - m[0][2] * m[2][0]) / det;
    r[1][2] = (m[0][2] * m[1][0] - m[0][0] * m[1][2]) / det;
    r[2][0] = (m[1][0] * m[2][1] - m[1][1] * m[2][0]) / det;
    r[2][1] = (m[0][1] * m[2][0] - m[0][0] * m[2][1]) / det;
    r[2][2] = (m[0][0] * m[1][1] - m[0][1] * m[1][0]) / det;
    return r;
}

// Colour-space constants in float, derived once from the double definitions above.
struct ColourSpace {
    std::array<std::array<float, 3>, 3> toXyz{};    // linear RGB -> XYZ / white (white-normalised)
    std::array<std::array<float, 3>, 3> fromXyz{};  // XYZ / white -> linear RGB
    ColourSpace() {
        const Mat3 inv = inverse(kRgbToXyz);
        std::array<double, 3> white{};
        for (std::size_t i = 0; i < 3; ++i) white[i] = kRgbToXyz[i][0] + kRgbToXyz[i][1] + kRgbToXyz[i][2];
        for (std::size_t i = 0; i < 3; ++i)
            for (std::size_t j = 0; j < 3; ++j) {
                toXyz[i][j] = static_cast<float>(kRgbToXyz[i][j] / white[i]);
                fromXyz[i][j] = static_cast<float>(inv[i][j] * white[j]);
            }
    }
};

const ColourSpace& colourSpace() {
    static const ColourSpace space;
    return space;
}

struct Lab {
    float l, a, b;
};

float labF(float t) {
    constexpr float delta = 6.0f / 29.0f;
    return t > delta * delta * delta ? std::cbrt(t) : t / (3.0f * delta * delta) + 4.0f / 29.0f;
}

// Clamped linear RGB -> Hunt-adjusted L*a*b*.
Lab huntLab(float r, float g, float b) {
    const auto& m = colourSpace().toXyz;
    const float x = m[0][0] * r + m[0][1] * g + m[0][2] * b;
    const float y = m[1][0] * r + m[1][1] * g + m[1][2] * b;
    const float z = m[2][0] * r + m[2][1] * g + m[2][2] * b;
    const float fx = labF(x), fy = labF(y), fz = labF(z);
    const float l = 116.0f * fy - 16.0f;
    return {l, 0.01f * l * 500.0f * (fx - fy), 0.01f * l * 200.0f * (fy - fz)};
}

float hyab(const Lab& p, const Lab& q) {
    const float da = p.a - q.a, db = p.b - q.b;
    return std::abs(p.l - q.l) + std::sqrt(da * da + db * db);
}

// The 1-D factors of a normalised CSF kernel: filtered = sum_i scale_i * (e_i (x) e_i)(image).
struct CsfKernel {
    std::vector<std::vector<float>> horizontal;  // e_i * scale_i
    std::vector<std::vector<float>> vertical;    // e_i
};

CsfKernel csfKernel(const Csf& csf, double ppd, int radius) {
    const std::array<std::pair<double, double>, 2> terms{{{csf.a1, csf.b1}, {csf.a2, csf.b2}}};
    std::vector<std::vector<double>> shapes;
    std::vector<double> weights;
    double total = 0.0;  // sum of the 2-D kernel over the square
    for (const auto& [a, b] : terms) {
        if (a == 0.0) continue;
        std::vector<double> e;
        double sum = 0.0;
        for (int i = -radius; i <= radius; ++i) {
            const double x = i / ppd;
            e.push_back(std::exp(-std::numbers::pi * std::numbers::pi * x * x / b));
            sum += e.back();
        }
        const double weight = a * std::sqrt(std::numbers::pi / b);
        total += weight * sum * sum;
        shapes.push_back(std::move(e));
        weights.push_back(weight);
    }
    // The narrow Gaussians (A, RG: sigma ~1 pixel at 67 PPD) fall below 1e-9 of their peak
    // well inside the radius; those taps are dropped, after normalising over the full square,
    // as they cannot change a float result.
    CsfKernel kernel;
    for (std::size_t i = 0; i < shapes.size(); ++i) {
        std::size_t trim = 0;
        while (trim < static_cast<std::size_t>(radius) && shapes[i][trim] < 1e-9) ++trim;
        std::vector<float> h, v;
        for (std::size_t k = trim; k + trim < shapes[i].size(); ++k) {
            h.push_back(static_cast<float>(shapes[i][k] * weights[i] / total));
            v.push_back(static_cast<float>(shapes[i][k]));
        }
        kernel.horizontal.push_back(std::move(h));
        kernel.vertical.push_back(std::move(v));
    }
    return kernel;
}

// Positive weights scaled to sum 1, negative ones to sum -1.
std::vector<float> normaliseSigned(const std::vector<double>& k) {
    double pos = 0.0, neg = 0.0;
    for (const double v : k) (v > 0.0 ? pos : neg) += v;
    std::vector<float> out;
    out.reserve(k.size());
    for (const double v : k) out.push_back(static_cast<float>(v > 0.0 ? v / pos : v < 0.0 ? -v / neg : 0.0));
    return out;
}

struct FeatureKernels {
    std::vector<float> g, dg, ddg;
};

FeatureKernels featureKernels(double ppd) {
    const double sigma = 0.5 * kFeatureWidthDegrees * ppd;
    const int radius = static_cast<int>(std::ceil(3.0 * sigma));
    std::vector<double> g, dg, ddg;
    double sum = 0.0;
    for (int i = -radius; i <= radius; ++i) {
        const double x = i;
        const double gauss = std::exp(-x * x / (2.0 * sigma * sigma));
        g.push_back(gauss);
        dg.push_back(-x * gauss);
        ddg.push_back((x * x / (sigma * sigma) - 1.0) * gauss);
        sum += gauss;
    }
    FeatureKernels k;
    for (const double v : g) k.g.push_back(static_cast<float>(v / sum));
    k.dg = normaliseSigned(dg);
    k.ddg = normaliseSigned(ddg);
    return k;
}

// What one image contributes to the per-pixel comparison.
struct Prepared {
    std::vector<float> l, a, b;      // Hunt-adjusted L*a*b* of the CSF-filtered image
    std::vector<float> edge, point;  // feature magnitudes
};

Prepared prepare(const Image& image, const std::array<int, 3>& channels, const std::array<CsfKernel, 3>& csf,
                 const FeatureKernels& features) {
    const int width = image.width, height = image.height;
    const std::size_t n = image.pixelCount();
    const auto w = static_cast<std::size_t>(width);
    const auto stride = static_cast<std::size_t>(image.channels);
    const auto& m = colourSpace().toXyz;

    // YyCxCz planes and the normalised luminance Y/Yn (for the feature pipeline).
    std::array<std::vector<float>, 3> ycc;
    for (auto& p : ycc) p.resize(n);
    std::vector<float> luminance(n);
    forEachRow(height, [&](int y) {
        for (std::size_t x = 0; x < w; ++x) {
            const std::size_t i = static_cast<std::size_t>(y) * w + x;
            const float* p = &image.pixels[i * stride];
            const float r = std::clamp(p[channels[0]], 0.0f, 1.0f);
            const float g = std::clamp(p[channels[1]], 0.0f, 1.0f);
            const float b = std::clamp(p[channels[2]], 0.0f, 1.0f);
            const float xn = m[0][0] * r + m[0][1] * g + m[0][2] * b;
            const float yn = m[1][0] * r + m[1][1] * g + m[1][2] * b;
            const float zn = m[2][0] * r + m[2][1] * g + m[2][2] * b;
            ycc[0][i] = 116.0f * yn - 16.0f;
            ycc[1][i] = 500.0f * (xn - yn);
            ycc[2][i] = 200.0f * (yn - zn);
            luminance[i] = yn;
        }
    });

    // CSF filtering of each channel.
    std::array<std::vector<float>, 3> filtered;
    std::vector<float> term;
    for (std::size_t c = 0; c < 3; ++c) {
        for (std::size_t t = 0; t < csf[c].horizontal.size(); ++t) {
            convolveSeparable(ycc[c], t == 0 ? filtered[c] : term, width, height, csf[c].horizontal[t],
                              csf[c].vertical[t]);
            if (t > 0)
                for (std::size_t i = 0; i < n; ++i) filtered[c][i] += term[i];
        }
    }
    ycc = {};

    // Back to linear RGB, clamped, then Hunt-adjusted L*a*b*.
    Prepared out;
    out.l.resize(n);
    out.a.resize(n);
    out.b.resize(n);
    const auto& inv = colourSpace().fromXyz;
    forEachRow(height, [&](int y) {
        for (std::size_t x = 0; x < w; ++x) {
            const std::size_t i = static_cast<std::size_t>(y) * w + x;
            const float yn = (filtered[0][i] + 16.0f) / 116.0f;
            const float xn = filtered[1][i] / 500.0f + yn;
            const float zn = yn - filtered[2][i] / 200.0f;
            const float r = std::clamp(inv[0][0] * xn + inv[0][1] * yn + inv[0][2] * zn, 0.0f, 1.0f);
            const float g = std::clamp(inv[1][0] * xn + inv[1][1] * yn + inv[1][2] * zn, 0.0f, 1.0f);
            const float b = std::clamp(inv[2][0] * xn + inv[2][1] * yn + inv[2][2] * zn, 0.0f, 1.0f);
            const Lab lab = huntLab(r, g, b);
            out.l[i] = lab.l;
            out.a[i] = lab.a;
            out.b[i] = lab.b;
        }
    });
    filtered = {};

    // Feature magnitudes: 3 horizontal passes shared by 4 vertical ones.
    std::vector<float> hg, hd, hdd, fx, fy;
    convolveRows(luminance, hg, width, height, features.g);
    convolveRows(luminance, hd, width, height, features.dg);
    convolveRows(luminance, hdd, width, height, features.ddg);
    auto magnitude = [&](std::vector<float>& dst, const std::vector<float>& alongX, const std::vector<float>& alongY) {
        dst.resize(n);
        for (std::size_t i = 0; i < n; ++i) dst[i] = std::sqrt(alongX[i] * alongX[i] + alongY[i] * alongY[i]);
    };
    convolveColumns(hd, fx, width, height, features.g);
    convolveColumns(hg, fy, width, height, features.dg);
    magnitude(out.edge, fx, fy);
    convolveColumns(hdd, fx, width, height, features.g);
    convolveColumns(hg, fy, width, height, features.ddg);
    magnitude(out.point, fx, fy);
    return out;
}

}  // namespace

double flipPixelsPerDegree(double distance, double resolutionX, double monitorWidth) {
    return distance * (resolutionX / monitorWidth) * (std::numbers::pi / 180.0);
}

double flip(const Image& reference, const Image& test, const FlipOptions& options, Image* errorMap) {
    requireComparable(reference, test, "flip");
    const double ppd = options.pixelsPerDegree;
    if (!(ppd > 0.0) || !std::isfinite(ppd))
        throw Error("flip: pixels per degree must be positive, got " + std::to_string(ppd));

    const int csfRadius =
        static_cast<int>(std::ceil(3.0 * std::sqrt(kCsfWidestB / (2.0 * std::numbers::pi * std::numbers::pi)) * ppd));
    const std::array<CsfKernel, 3> csf{csfKernel(kCsfAchromatic, ppd, csfRadius),
                                       csfKernel(kCsfRedGreen, ppd, csfRadius),
                                       csfKernel(kCsfBlueYellow, ppd, csfRadius)};
    const FeatureKernels features = featureKernels(ppd);

    const Prepared r = prepare(reference, colourChannels(reference, "flip"), csf, features);
    const Prepared t = prepare(test, colourChannels(test, "flip"), csf, features);

    const float cmax = std::pow(hyab(huntLab(0.0f, 1.0f, 0.0f), huntLab(0.0f, 0.0f, 1.0f)), static_cast<float>(kQc));
    const float pccmax = static_cast<float>(kPc) * cmax;
    const float pt = static_cast<float>(kPt);

    const auto w = static_cast<std::size_t>(reference.width);
    if (errorMap) *errorMap = Image::make(reference.width, reference.height, 1);
    const double sum = sumRows(reference.height, [&](int y) {
        double rowSum = 0.0;
        for (std::size_t x = 0; x < w; ++x) {
            const std::size_t i = static_cast<std::size_t>(y) * w + x;
            const float de =
                std::pow(hyab({r.l[i], r.a[i], r.b[i]}, {t.l[i], t.a[i], t.b[i]}), static_cast<float>(kQc));
            float colour = de < pccmax ? pt / pccmax * de : pt + (de - pccmax) / (cmax - pccmax) * (1.0f - pt);
            if (colour > 1.0f) colour = 1.0f;  // (NaN passes through)
            const float featureDiff = std::max(std::abs(r.edge[i] - t.edge[i]), std::abs(r.point[i] - t.point[i]));
            const float feature = std::sqrt(featureDiff * std::numbers::sqrt2_v<float> * 0.5f);  // ^qf, qf = 0.5
            const float error = std::pow(colour, 1.0f - feature);
            if (errorMap) errorMap->pixels[i] = error;
            rowSum += error;
        }
        return rowSum;
    });
    return sum / static_cast<double>(reference.pixelCount());
}

}  // namespace engine::capture
