// SPDX-License-Identifier: MIT
#pragma once
// CPU-side texel work the GL and Vulkan backends do themselves so that they match the soft backend bit for
// bit: 16-bit float conversion (round to nearest even, Imath) and mip generation. The
// encode/decode rules are engine/render/pixel_codec.hpp's (GL 4.5 §2.3.5, §17.3.6.3):
// UNORM clamps and rounds to nearest, NaN stores 0; sRGB decodes with the exact curve (table)
// and encodes with the exact formula.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "engine/render/format.hpp"

namespace engine::render {

// Bytes per texel as stored by the GPU APIs (16F: 2 bytes per channel).
int storedBytesPerPixel(Format format);

// Converts the caller's level data (16F formats given as 32-bit floats) to the stored layout.
std::vector<std::byte> toStored(Format format, std::span<const std::byte> level, std::size_t pixels);

// One texel of `value` in the stored layout, as the soft backend stores it (for clears).
std::vector<std::byte> encodeTexel(Format format, const glm::vec4& value);

// Level `width x height` from the stored level above it (2x2 box in linear light; odd sizes
// repeat the last row/column), as the soft backend's generateMipLevel.
std::vector<std::byte> generateMip(Format format, std::span<const std::byte> above, int aboveWidth, int aboveHeight,
                                   int width, int height);

}  // namespace engine::render
