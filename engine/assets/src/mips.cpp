// SPDX-License-Identifier: MIT
#include "engine/assets/mips.hpp"

#include <algorithm>
#include <cmath>

#include "engine/core/error.hpp"

namespace engine::assets {

namespace {

// The exact sRGB curves (IEC 61966-2-1).
float srgbToLinear(float s) { return s <= 0.04045f ? s / 12.92f : std::pow((s + 0.055f) / 1.055f, 2.4f); }
float linearToSrgb(float l) { return l <= 0.0031308f ? l * 12.92f : 1.055f * std::pow(l, 1.0f / 2.4f) - 0.055f; }

std::uint8_t toCode(float v) { return static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)); }

// One level as float RGBA: linear light, premultiplied colour. The working form of every level.
struct Level {
    int width = 0;
    int height = 0;
    std::vector<float> texels;  // width * height * 4
};

Level decode(const RgbaImage& image) {
    float table[256];
    for (int i = 0; i < 256; ++i)
        table[i] = image.srgb ? srgbToLinear(static_cast<float>(i) / 255.0f) : static_cast<float>(i) / 255.0f;
    Level level{image.width, image.height, std::vector<float>(image.pixelCount() * 4)};
    for (std::size_t t = 0; t < image.pixelCount(); ++t) {
        const std::uint8_t* src = image.pixels.data() + t * 4;
        const float a = static_cast<float>(src[3]) / 255.0f;
        // Straight texels are premultiplied here; premultiplied ones already are.
        const float k = image.alpha == render::AlphaMode::Straight ? a : 1.0f;
        float* dst = level.texels.data() + t * 4;
        for (int c = 0; c < 3; ++c) dst[c] = table[src[c]] * k;
        dst[3] = a;
    }
    return level;
}

// 2x2 box filter; at an odd edge the last row/column is clamped (counted twice).
Level downsample(const Level& src) {
    Level dst{std::max(1, src.width / 2), std::max(1, src.height / 2), {}};
    dst.texels.resize(static_cast<std::size_t>(dst.width) * static_cast<std::size_t>(dst.height) * 4);
    for (int y = 0; y < dst.height; ++y)
        for (int x = 0; x < dst.width; ++x) {
            const int x0 = std::min(2 * x, src.width - 1), x1 = std::min(2 * x + 1, src.width - 1);
            const int y0 = std::min(2 * y, src.height - 1), y1 = std::min(2 * y + 1, src.height - 1);
            const auto at = [&](int sx, int sy) {
                return src.texels.data() + (static_cast<std::size_t>(sy) * static_cast<std::size_t>(src.width) +
                                            static_cast<std::size_t>(sx)) *
                                               4;
            };
            float* out =
                dst.texels.data() +
                (static_cast<std::size_t>(y) * static_cast<std::size_t>(dst.width) + static_cast<std::size_t>(x)) * 4;
            for (int c = 0; c < 4; ++c)
                out[c] = 0.25f * (at(x0, y0)[c] + at(x1, y0)[c] + at(x0, y1)[c] + at(x1, y1)[c]);
        }
    return dst;
}

// Fraction of texels whose stored alpha code, after scaling by `scale`, passes alpha >= cutoff.
float scaledCoverage(const Level& level, float scale, float cutoff) {
    std::size_t passed = 0;
    const std::size_t count = level.texels.size() / 4;
    for (std::size_t t = 0; t < count; ++t)
        if (static_cast<float>(toCode(level.texels[t * 4 + 3] * scale)) / 255.0f >= cutoff) ++passed;
    return static_cast<float>(passed) / static_cast<float>(count);
}

// Castaño's alpha scale: the scale whose coverage at the cutoff is closest to `target`.
// Coverage only grows with the scale, so bisect on it (in [0, 256]: any larger scale already
// passes every texel with alpha >= 1/256 of the cutoff).
float coverageScale(const Level& level, float cutoff, float target) {
    float lo = 0.0f;
    float hi = 256.0f;
    if (scaledCoverage(level, hi, cutoff) < target) return hi;
    for (int i = 0; i < 32; ++i) {  // lo: coverage < target, hi: coverage >= target
        const float mid = 0.5f * (lo + hi);
        if (scaledCoverage(level, mid, cutoff) >= target) hi = mid;
        else lo = mid;
    }
    const float above = scaledCoverage(level, hi, cutoff) - target;
    const float below = target - scaledCoverage(level, lo, cutoff);
    return below < above ? lo : hi;
}

RgbaImage encode(const Level& level, const RgbaImage& like, render::AlphaMode output, float alphaScale) {
    RgbaImage image = RgbaImage::make(level.width, level.height, output);
    image.srgb = like.srgb;
    const auto encodeColour = [&](float linear) {
        return toCode(like.srgb ? linearToSrgb(std::clamp(linear, 0.0f, 1.0f)) : linear);
    };
    for (std::size_t t = 0; t < image.pixelCount(); ++t) {
        const float* src = level.texels.data() + t * 4;
        std::uint8_t* dst = image.pixels.data() + t * 4;
        const float a = src[3];
        const float scaled = std::min(1.0f, a * alphaScale);
        for (int c = 0; c < 3; ++c) {
            float colour = 0.0f;
            if (a > 0.0f) colour = output == render::AlphaMode::Premultiplied ? src[c] * (scaled / a) : src[c] / a;
            dst[c] = encodeColour(colour);
        }
        dst[3] = toCode(scaled);
    }
    return image;
}

}  // namespace

std::vector<RgbaImage> generateMips(const RgbaImage& level0, const MipOptions& options) {
    if (level0.empty() || level0.pixels.size() != level0.pixelCount() * 4)
        throw Error("generateMips: the image is empty or its pixel buffer does not match its size");
    const bool preserve = options.preserveCoverageCutoff > 0.0f && options.preserveCoverageCutoff <= 1.0f;

    Level level = decode(level0);
    const float targetCoverage = preserve ? alphaCoverage(level0, options.preserveCoverageCutoff) : 0.0f;
    std::vector<RgbaImage> levels;
    levels.push_back(encode(level, level0, options.output, 1.0f));
    while ((level.width > 1 || level.height > 1) &&
           (options.maxLevels <= 0 || static_cast<int>(levels.size()) < options.maxLevels)) {
        level = downsample(level);  // always from the unscaled previous level
        const float scale = preserve ? coverageScale(level, options.preserveCoverageCutoff, targetCoverage) : 1.0f;
        levels.push_back(encode(level, level0, options.output, scale));
    }
    return levels;
}

std::vector<RgbaImage> generateCoveragePreservingMips(const RgbaImage& level0, float cutoff, render::AlphaMode output) {
    if (!(cutoff > 0.0f && cutoff <= 1.0f))
        throw Error("generateCoveragePreservingMips: cutoff " + std::to_string(cutoff) + " is not in (0, 1]");
    MipOptions options;
    options.output = output;
    options.preserveCoverageCutoff = cutoff;
    return generateMips(level0, options);
}

float alphaCoverage(const RgbaImage& image, float cutoff) {
    if (image.empty()) return 0.0f;
    std::size_t passed = 0;
    for (std::size_t t = 0; t < image.pixelCount(); ++t)
        if (static_cast<float>(image.pixels[t * 4 + 3]) / 255.0f >= cutoff) ++passed;
    return static_cast<float>(passed) / static_cast<float>(image.pixelCount());
}

render::TextureData textureData(const std::vector<RgbaImage>& levels) {
    render::TextureData data;
    for (const RgbaImage& level : levels) data.levels.push_back(level.bytes());
    return data;
}

}  // namespace engine::assets
