// SPDX-License-Identifier: MIT
#include "engine/capture/image.hpp"

#include "engine/core/error.hpp"

#include <algorithm>

namespace engine::capture {
namespace {

void requireSize(int width, int height, std::size_t channels) {
    if (width <= 0 || height <= 0 || channels == 0)
        throw Error("image: size " + std::to_string(width) + "x" + std::to_string(height) + "x" +
                    std::to_string(channels) + " is empty; width, height and channels must be positive");
}

// Copies `value` into every pixel of an interleaved buffer.
template <typename T>
void fillPixels(std::vector<T>& pixels, int channels, std::span<const T> value) {
    if (value.size() != static_cast<std::size_t>(channels))
        throw Error("image fill: " + std::to_string(value.size()) + " values given for " + std::to_string(channels) +
                    " channels");
    for (std::size_t i = 0; i < pixels.size(); i += value.size())
        std::copy(value.begin(), value.end(), pixels.begin() + static_cast<std::ptrdiff_t>(i));
}

bool isAlphaName(std::string_view name) {
    const auto dot = name.rfind('.');
    const std::string_view last = dot == std::string_view::npos ? name : name.substr(dot + 1);
    return last == "A" || last == "a" || last == "alpha" || last == "Alpha";
}

// Image and Image8 differ only in their sample type. (clang-tidy 14 does not see the move of
// channelNames into the dependent ImageT below, hence the NOLINT.)
template <typename ImageT>
ImageT makeZeroed(int width, int height,
                  std::vector<std::string> channelNames,  // NOLINT(performance-unnecessary-value-param)
                  AlphaMode alpha) {
    requireSize(width, height, channelNames.size());
    ImageT image;
    image.width = width;
    image.height = height;
    image.channels = static_cast<int>(channelNames.size());
    image.channelNames = std::move(channelNames);
    image.pixels.assign(image.pixelCount() * static_cast<std::size_t>(image.channels), 0);
    image.alpha = alpha;
    return image;
}

// make(width, height, channels): zeros, the channels named as a file would name them.
template <typename ImageT>
ImageT makeWithDefaultNames(int width, int height, int channels, AlphaMode alpha) {
    requireSize(width, height, static_cast<std::size_t>(std::max(channels, 0)));
    return ImageT::make(width, height, defaultChannelNames(channels), alpha);
}

}  // namespace

const char* alphaModeName(AlphaMode mode) { return mode == AlphaMode::Straight ? "straight" : "premultiplied"; }

std::vector<std::string> defaultChannelNames(int channels) {
    switch (channels) {
        case 1: return {"Y"};
        case 2: return {"Y", "A"};
        case 3: return {"R", "G", "B"};
        default: break;
    }
    std::vector<std::string> names = {"R", "G", "B", "A"};
    for (int c = 4; c < channels; ++c) names.push_back("channel" + std::to_string(c));
    names.resize(static_cast<std::size_t>(std::max(channels, 0)));
    return names;
}

int findAlphaChannel(std::span<const std::string> channelNames) {
    for (std::size_t c = 0; c < channelNames.size(); ++c)
        if (isAlphaName(channelNames[c])) return static_cast<int>(c);
    return -1;
}

Image Image::make(int width, int height, std::vector<std::string> channelNames, AlphaMode alpha) {
    return makeZeroed<Image>(width, height, std::move(channelNames), alpha);
}

Image Image::make(int width, int height, int channels, AlphaMode alpha) {
    return makeWithDefaultNames<Image>(width, height, channels, alpha);
}

void Image::fill(std::span<const float> value) { fillPixels(pixels, channels, value); }

int Image::channelIndex(std::string_view name) const {
    for (std::size_t c = 0; c < channelNames.size(); ++c)
        if (channelNames[c] == name) return static_cast<int>(c);
    return -1;
}

Image8 Image8::make(int width, int height, std::vector<std::string> channelNames, AlphaMode alpha) {
    return makeZeroed<Image8>(width, height, std::move(channelNames), alpha);
}

Image8 Image8::make(int width, int height, int channels, AlphaMode alpha) {
    return makeWithDefaultNames<Image8>(width, height, channels, alpha);
}

void Image8::fill(std::span<const std::uint8_t> value) { fillPixels(pixels, channels, value); }

}  // namespace engine::capture
