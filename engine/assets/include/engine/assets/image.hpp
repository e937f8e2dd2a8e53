// SPDX-License-Identifier: MIT
#pragma once
// Decoded texture images as glTF uses them: 8-bit RGBA, rows top to bottom, colour codes
// sRGB-encoded (base colour textures are sRGB, glTF 2.0 §3.9.2), alpha linear and straight.
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "engine/render/texture.hpp"

namespace engine::assets {

// Refused before any pixel buffer is allocated (the render interface's texture caps).
struct ImageLimits {
    int maxDimension = render::kMaxTextureDimension;
    std::uint64_t maxDecodedBytes = render::kMaxTextureBytes;  // of the RGBA8 result
};

struct RgbaImage {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> pixels;  // width * height * 4: R, G, B, A
    render::AlphaMode alpha = render::AlphaMode::Straight;
    bool srgb = true;  // colour codes are sRGB-encoded; false: linear data (alpha is always linear)

    // A width x height image of zeros; throws engine::Error for a non-positive size.
    static RgbaImage make(int width, int height, render::AlphaMode alpha = render::AlphaMode::Straight);

    std::size_t index(int x, int y) const {
        return (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)) * 4;
    }
    std::uint8_t* texel(int x, int y) { return pixels.data() + index(x, y); }
    const std::uint8_t* texel(int x, int y) const { return pixels.data() + index(x, y); }
    std::size_t pixelCount() const { return static_cast<std::size_t>(width) * static_cast<std::size_t>(height); }
    bool empty() const { return width <= 0 || height <= 0; }
    std::span<const std::byte> bytes() const { return std::as_bytes(std::span(pixels)); }
};

// Decodes an encoded image held in memory (PNG, JPEG, or anything else OpenImageIO reads
// from memory) to RGBA8 with straight alpha: grey becomes RGB, a missing alpha becomes 255,
// 16-bit data is rounded to 8 bits. `name` is only used in error messages. Throws
// engine::Error("<name>: ...") for data that is not an image, truncated or over the limits;
// the size is checked from the header before the pixels are allocated.
RgbaImage decodeImage(std::span<const std::uint8_t> encoded, const std::string& name, const ImageLimits& limits = {});

}  // namespace engine::assets
