// SPDX-License-Identifier: MIT
#pragma once
// The exact sRGB transfer curve (IEC 61966-2-1), not a 2.2 gamma approximation: the
// piecewise function with the linear toe, so 8-bit codes round-trip exactly.
#include <cstdint>

namespace engine::capture {

// Encoded value in [0,1] -> linear light. Computed in double, so it is the curve to float precision.
float srgbToLinear(float encoded);
// Linear light -> encoded value, unclamped (values outside [0,1] are mirrored through the curve's ends).
float linearToSrgb(float linear);

// 8-bit code -> linear light (table of the exact curve).
float decodeSrgb8(std::uint8_t code);
// Linear light -> nearest 8-bit code: clamped to [0,1], NaN -> 0, rounded half up.
std::uint8_t encodeSrgb8(float linear);

// For channels that carry no colour (alpha, masks): value -> code with the same clamping and rounding.
std::uint8_t encodeUnorm8(float value);
inline float decodeUnorm8(std::uint8_t code) { return static_cast<float>(code) / 255.0f; }

}  // namespace engine::capture
