// SPDX-License-Identifier: MIT
#include "engine/capture/image_convert.hpp"

#include "engine/capture/srgb.hpp"

#include <algorithm>

namespace engine::capture {
namespace {

// Applies `op(pixelIndex, alphaValue)` to the colour channels of every pixel that has an alpha.
template <typename Op>
void forEachColourWithAlpha(Image& image, Op op) {
    const int alphaIndex = image.alphaChannel();
    if (alphaIndex < 0) return;
    const auto channels = static_cast<std::size_t>(image.channels);
    for (std::size_t base = 0; base < image.pixels.size(); base += channels) {
        const float a = image.pixels[base + static_cast<std::size_t>(alphaIndex)];
        for (std::size_t c = 0; c < channels; ++c)
            if (static_cast<int>(c) != alphaIndex) op(image.pixels[base + c], a);
    }
}

// out's values from in's, sample by sample: the alpha channel (alphaIndex) through `alpha`,
// every other channel through `colour`. Both images have in's size and channels.
template <typename In, typename Out, typename Alpha, typename Colour>
void convertSamples(const In& in, Out& out, int alphaIndex, Alpha alpha, Colour colour) {
    const auto channels = static_cast<std::size_t>(in.channels);
    for (std::size_t i = 0; i < in.pixels.size(); ++i) {
        const bool isAlpha = static_cast<int>(i % channels) == alphaIndex;
        out.pixels[i] = isAlpha ? alpha(in.pixels[i]) : colour(in.pixels[i]);
    }
}

}  // namespace

Image decodeSrgbImage(const Image8& image) {
    Image out = Image::make(image.width, image.height, image.channelNames, image.alpha);
    convertSamples(image, out, image.alphaChannel(), decodeUnorm8, decodeSrgb8);
    return out;
}

Image8 encodeSrgbImage(const Image& image) {
    Image straight = image;
    unpremultiply(straight);
    Image8 out = Image8::make(image.width, image.height, image.channelNames, AlphaMode::Straight);
    convertSamples(straight, out, image.alphaChannel(), encodeUnorm8, encodeSrgb8);
    return out;
}

Image8 quantizeUnorm8(const Image& image) {
    Image8 out = Image8::make(image.width, image.height, image.channelNames, image.alpha);
    std::transform(image.pixels.begin(), image.pixels.end(), out.pixels.begin(), encodeUnorm8);
    return out;
}

void premultiply(Image& image) {
    if (image.alpha == AlphaMode::Premultiplied) return;
    forEachColourWithAlpha(image, [](float& colour, float a) { colour *= a; });
    image.alpha = AlphaMode::Premultiplied;
}

void unpremultiply(Image& image) {
    if (image.alpha == AlphaMode::Straight) return;
    forEachColourWithAlpha(image, [](float& colour, float a) {
        if (a != 0.0f) colour /= a;
    });
    image.alpha = AlphaMode::Straight;
}

}  // namespace engine::capture
