// SPDX-License-Identifier: MIT
#include "engine/capture/srgb.hpp"

#include <array>
#include <cmath>

namespace engine::capture {
namespace {

double toLinear(double v) { return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4); }
double toEncoded(double v) { return v <= 0.0031308 ? v * 12.92 : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055; }

const std::array<float, 256>& decodeTable() {
    static const std::array<float, 256> table = [] {
        std::array<float, 256> t{};
        for (int code = 0; code < 256; ++code)
            t[static_cast<std::size_t>(code)] = static_cast<float>(toLinear(code / 255.0));
        return t;
    }();
    return table;
}

// Shared quantiser: [0,1] -> 0..255, rounding half up; NaN lands on 0 because !(v > 0) holds for it.
std::uint8_t quantize(double v) {
    if (!(v > 0.0)) return 0;
    if (v >= 1.0) return 255;
    return static_cast<std::uint8_t>(std::floor(v * 255.0 + 0.5));
}

}  // namespace

float srgbToLinear(float encoded) {
    const double v = encoded;
    return static_cast<float>(v < 0.0 ? -toLinear(-v) : toLinear(v));
}

float linearToSrgb(float linear) {
    const double v = linear;
    return static_cast<float>(v < 0.0 ? -toEncoded(-v) : toEncoded(v));
}

float decodeSrgb8(std::uint8_t code) { return decodeTable()[code]; }

std::uint8_t encodeSrgb8(float linear) {
    if (!(linear > 0.0f)) return 0;  // also NaN
    if (linear >= 1.0f) return 255;
    return quantize(toEncoded(linear));
}

std::uint8_t encodeUnorm8(float value) { return quantize(value); }

}  // namespace engine::capture
