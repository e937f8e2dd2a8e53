// SPDX-License-Identifier: MIT
#pragma once
// Reading textures and captures (PNG, TGA, JPEG, EXR, anything OpenImageIO reads).
// Every failure (missing, truncated or corrupt file, unsupported layout, over the size
// cap) throws engine::Error naming the file, with OpenImageIO's own explanation.
#include <cstdint>
#include <filesystem>

#include "engine/capture/image.hpp"

namespace engine::capture {

struct ReadOptions {
    // Files larger than this are refused after the header is read and before any pixel
    // buffer is allocated, so a hostile or broken header cannot exhaust memory.
    int maxWidth = 16384;
    int maxHeight = 16384;
    std::uint64_t maxDecodedBytes = std::uint64_t{1} << 30;  // of the returned pixel buffer
    // true: sRGB-encoded integer files are decoded to linear light.
    // false: values come back as code / max code, as stored, which is what idiff compares.
    bool linearize = true;
};

// Any supported file -> float. Colour is linear light unless options.linearize is false.
// PNG/TGA/JPEG come back Straight (OpenImageIO is asked not to premultiply),
// EXR and other float formats Premultiplied.
Image readImage(const std::filesystem::path& path, const ReadOptions& options = {});

// An 8-bit file's stored codes, untouched (sRGB-encoded colour, straight alpha for PNG).
// Files stored with more than 8 bits per channel are refused rather than quantised.
Image8 readImage8(const std::filesystem::path& path, const ReadOptions& options = {});

}  // namespace engine::capture
