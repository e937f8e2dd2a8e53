// SPDX-License-Identifier: MIT
#pragma once
// Pixel formats of textures and render targets, and what each implies for blending.
// The API rules (GL 4.5 §17.3.6, Vulkan "Blending"): UNORM/sRGB targets clamp source,
// destination and factors to [0,1] and round to nearest on store; float targets never clamp.
#include <cstdint>
#include <string_view>

namespace engine::render {

enum class Format : std::uint8_t {
    RGBA8_UNORM,
    RGBA8_SRGB,  // stored sRGB-encoded; decoded before blending/filtering, encoded after
    R8_UNORM,
    RG8_UNORM,
    RGBA16F,
    RG16F,
    R16F,
    RGBA32F,
    R32F,
    D32F,  // depth
};

struct FormatInfo {
    std::string_view name;
    std::uint8_t channels;       // colour channels stored (R, RG or RGBA); 1 for depth
    std::uint8_t bytesPerPixel;  // per sample
    bool isFloat;
    bool isSrgb;
    bool isDepth;
    bool isNormalized() const { return !isFloat && !isDepth; }
};

const FormatInfo& formatInfo(Format format);
inline std::string_view formatName(Format format) { return formatInfo(format).name; }

}  // namespace engine::render
