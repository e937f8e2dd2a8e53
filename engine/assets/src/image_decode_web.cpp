// SPDX-License-Identifier: MIT
// Decoding glTF images held in memory in the web page's build, which has no OpenImageIO: stb_image
// (Debian's libstb headers), PNG and JPEG only, the two formats glTF 2.0 §3.8.1 allows. The same
// caps as the native decoder (image_decode.cpp) are checked from the header before any pixel is
// allocated, and the same expansion to straight-alpha RGBA8 (grey to RGB, a missing alpha opaque),
// which stb_image does itself when asked for 4 channels. 8-bit images decode to the same bytes as
// natively; a 16-bit one is cut to its high byte here where OpenImageIO rounds (the racer's
// content has none).
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#define STBI_ONLY_JPEG
#define STBI_NO_STDIO
#include <stb_image.h>

#include <climits>
#include <cstdint>
#include <cstring>
#include <memory>

#include "engine/assets/image.hpp"
#include "engine/core/error.hpp"
#include "engine/core/file_signature.hpp"

namespace engine::assets {

RgbaImage decodeImage(std::span<const std::uint8_t> encoded, const std::string& name, const ImageLimits& limits) {
    const auto fail = [&](const std::string& what) { return Error(name + ": " + what); };
    if (encoded.empty()) throw fail("empty image data");
    if (encoded.size() > std::size_t(INT_MAX)) throw fail("image data over 2 GiB");
    const auto* bytes = reinterpret_cast<const stbi_uc*>(encoded.data());
    const int length = int(encoded.size());
    int width = 0, height = 0, channels = 0;
    if (!stbi_info_from_memory(bytes, length, &width, &height, &channels))
        throw fail("not a PNG or JPEG image (glTF 2.0 images must be one of these): it " + describeFileStart(encoded));
    const std::string size = std::to_string(width) + "x" + std::to_string(height);
    if (width <= 0 || height <= 0) throw fail("zero-size image (" + size + ")");
    if (width > limits.maxDimension || height > limits.maxDimension)
        throw fail("image is " + size + ", over the size cap of " + std::to_string(limits.maxDimension) + "x" +
                   std::to_string(limits.maxDimension));
    const std::uint64_t decoded = std::uint64_t(width) * std::uint64_t(height) * 4;
    if (decoded > limits.maxDecodedBytes)
        throw fail("image is " + size + ", " + std::to_string(decoded) + " bytes decoded, over the cap of " +
                   std::to_string(limits.maxDecodedBytes) + " bytes");

    const std::unique_ptr<stbi_uc, void (*)(void*)> pixels(
        stbi_load_from_memory(bytes, length, &width, &height, &channels, 4), stbi_image_free);
    if (!pixels)
        throw fail(std::string("cannot read the pixels (truncated or corrupt image?): ") + stbi_failure_reason());
    RgbaImage image = RgbaImage::make(width, height, render::AlphaMode::Straight);
    std::memcpy(image.pixels.data(), pixels.get(), image.pixels.size());
    return image;
}

}  // namespace engine::assets
