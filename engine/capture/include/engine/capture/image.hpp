// SPDX-License-Identifier: MIT
#pragma once
// In-memory images exchanged with files: a float image (colour in linear light) for
// rendering and comparison, and an 8-bit image holding the exact stored codes of an
// 8-bit file. Pixels are interleaved, rows top to bottom: index = (y*width + x)*channels + c.
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace engine::capture {

// Whether colour has already been multiplied by alpha. PNG/TGA/JPEG store straight colour,
// EXR stores premultiplied colour; the distinction matters wherever alpha is 0 (straight
// colour survives there, premultiplied colour is 0).
enum class AlphaMode : std::uint8_t { Straight, Premultiplied };

const char* alphaModeName(AlphaMode mode);

// Channel names a file would get for this many channels: Y, YA, RGB, RGBA, then RGBA + "channelN".
std::vector<std::string> defaultChannelNames(int channels);

// Index of the alpha channel ("A", or a layer's ".A"; also "alpha"), or -1 when there is none.
int findAlphaChannel(std::span<const std::string> channelNames);

// Where sample (x, y, c) of an interleaved width x ... x channels image is.
inline std::size_t interleavedIndex(int width, int channels, int x, int y, int c) {
    return (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)) *
               static_cast<std::size_t>(channels) +
           static_cast<std::size_t>(c);
}

struct Image {
    int width = 0;
    int height = 0;
    int channels = 0;
    std::vector<std::string> channelNames;  // one per channel
    std::vector<float> pixels;              // width * height * channels, interleaved
    AlphaMode alpha = AlphaMode::Premultiplied;

    // A width x height image of zeros. Throws engine::Error for a non-positive size.
    static Image make(int width, int height, std::vector<std::string> channelNames,
                      AlphaMode alpha = AlphaMode::Premultiplied);
    static Image make(int width, int height, int channels, AlphaMode alpha = AlphaMode::Premultiplied);

    std::size_t index(int x, int y, int c) const { return interleavedIndex(width, channels, x, y, c); }
    float& at(int x, int y, int c) { return pixels[index(x, y, c)]; }
    float at(int x, int y, int c) const { return pixels[index(x, y, c)]; }

    // Sets every pixel to `value` (one entry per channel; throws engine::Error otherwise).
    void fill(std::span<const float> value);
    void fill(std::initializer_list<float> value) { fill(std::span<const float>(value.begin(), value.size())); }

    int channelIndex(std::string_view name) const;  // -1 when absent
    int alphaChannel() const { return findAlphaChannel(channelNames); }
    std::size_t pixelCount() const { return static_cast<std::size_t>(width) * static_cast<std::size_t>(height); }
    bool empty() const { return width <= 0 || height <= 0 || channels <= 0; }
};

// The codes of an 8-bit file as stored: colour sRGB-encoded (unless the file says linear),
// alpha linear. Kept separate from Image so exact 8-bit round trips never pass through float.
struct Image8 {
    int width = 0;
    int height = 0;
    int channels = 0;
    std::vector<std::string> channelNames;
    std::vector<std::uint8_t> pixels;
    AlphaMode alpha = AlphaMode::Straight;

    static Image8 make(int width, int height, std::vector<std::string> channelNames,
                       AlphaMode alpha = AlphaMode::Straight);
    static Image8 make(int width, int height, int channels, AlphaMode alpha = AlphaMode::Straight);

    std::size_t index(int x, int y, int c) const { return interleavedIndex(width, channels, x, y, c); }
    std::uint8_t& at(int x, int y, int c) { return pixels[index(x, y, c)]; }
    std::uint8_t at(int x, int y, int c) const { return pixels[index(x, y, c)]; }

    void fill(std::span<const std::uint8_t> value);
    void fill(std::initializer_list<std::uint8_t> value) {
        fill(std::span<const std::uint8_t>(value.begin(), value.size()));
    }

    int alphaChannel() const { return findAlphaChannel(channelNames); }
    std::size_t pixelCount() const { return static_cast<std::size_t>(width) * static_cast<std::size_t>(height); }
    bool empty() const { return width <= 0 || height <= 0 || channels <= 0; }
};

}  // namespace engine::capture
