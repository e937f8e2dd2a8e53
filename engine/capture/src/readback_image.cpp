// SPDX-License-Identifier: MIT
#include "engine/capture/readback_image.hpp"

#include "engine/capture/srgb.hpp"

namespace engine::capture {

Image imageFromReadback(const render::Readback& r) {
    const render::FormatInfo& info = render::formatInfo(r.format);
    if (info.isDepth) {
        Image depth = Image::make(r.width, r.height, std::vector<std::string>{"Z"}, AlphaMode::Straight);
        depth.pixels = r.values;
        return depth;
    }
    Image image = Image::make(r.width, r.height, 4, AlphaMode::Straight);
    for (int y = 0; y < r.height; ++y) {
        for (int x = 0; x < r.width; ++x) {
            float rgba[4] = {0.0f, 0.0f, 0.0f, 1.0f};
            for (int c = 0; c < r.channels; ++c) rgba[c] = r.at(x, y, c);
            for (int c = 0; c < 4; ++c) image.at(x, y, c) = (info.isSrgb && c < 3) ? srgbToLinear(rgba[c]) : rgba[c];
        }
    }
    return image;
}

}  // namespace engine::capture
