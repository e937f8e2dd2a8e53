// SPDX-License-Identifier: MIT
#include "layer_pictures.hpp"

#include <algorithm>
#include <cmath>

namespace racer {

namespace cap = engine::capture;

cap::Image layerPicture(const cap::CapturedLayer& layer, float nearPlane, float farPlane) {
    const cap::Image& in = layer.image;
    cap::Image out = cap::Image::make(in.width, in.height, 3, cap::AlphaMode::Straight);
    const bool depth = in.channels == 1 && in.channelNames.front() == "Z";
    for (int y = 0; y < in.height; ++y) {
        for (int x = 0; x < in.width; ++x) {
            for (int c = 0; c < 3; ++c) {
                float v = in.at(x, y, in.channels == 1 ? 0 : c);
                if (depth) {
                    // Reverse-Z: depth ~ near / distance; show 1 - log(distance/near) / log(far/near).
                    const float distance = v > 0.0f ? std::min(nearPlane / v, farPlane) : farPlane;
                    const float t = std::log(distance / nearPlane) / std::log(farPlane / nearPlane);
                    v = std::pow(std::clamp(1.0f - t, 0.0f, 1.0f), 2.2f);  // linear light for the PNG's sRGB
                } else if (in.channels == 1) {
                    // Masks are coverage values: show them as sRGB grey levels of the same number.
                    const float s = std::clamp(v, 0.0f, 1.0f);
                    v = s <= 0.04045f ? s / 12.92f : std::pow((s + 0.055f) / 1.055f, 2.4f);
                }
                out.at(x, y, c) = v;
            }
        }
    }
    return out;
}

}  // namespace racer
