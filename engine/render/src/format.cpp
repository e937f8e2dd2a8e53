// SPDX-License-Identifier: MIT
#include "engine/render/format.hpp"

#include <array>

namespace engine::render {

const FormatInfo& formatInfo(Format format) {
    // name, channels, bytes per sample, float, sRGB, depth
    static const std::array<FormatInfo, 10> kInfo = {{
        {"RGBA8_UNORM", 4, 4, false, false, false},
        {"RGBA8_SRGB", 4, 4, false, true, false},
        {"R8_UNORM", 1, 1, false, false, false},
        {"RG8_UNORM", 2, 2, false, false, false},
        {"RGBA16F", 4, 8, true, false, false},
        {"RG16F", 2, 4, true, false, false},
        {"R16F", 1, 2, true, false, false},
        {"RGBA32F", 4, 16, true, false, false},
        {"R32F", 1, 4, true, false, false},
        {"D32F", 1, 4, true, false, true},
    }};
    return kInfo[static_cast<std::size_t>(format)];
}

}  // namespace engine::render
