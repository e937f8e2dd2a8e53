// SPDX-License-Identifier: MIT
#pragma once
// Conversions between the in-memory representations: 8-bit stored codes <-> linear float,
// and straight <-> premultiplied colour. Alpha is never transfer-encoded; every other
// channel of an 8-bit image is treated as sRGB-encoded colour.
#include "engine/capture/image.hpp"

namespace engine::capture {

// 8-bit codes -> linear float (colour through the exact sRGB curve, alpha as code/255).
// The alpha mode is kept: straight codes give a straight image.
Image decodeSrgbImage(const Image8& image);

// Linear float -> 8-bit codes as a PNG stores them: colour sRGB-encoded, straight alpha
// (a premultiplied image is un-premultiplied first), clamped, NaN -> 0, rounded to nearest.
Image8 encodeSrgbImage(const Image& image);

// Values in [0,1] -> codes with no transfer curve (masks, depth, difference images):
// clamped, NaN -> 0, rounded to nearest. Keeps the alpha mode.
Image8 quantizeUnorm8(const Image& image);

// In place; no-ops for images without an alpha channel or already in the requested mode.
// Un-premultiplying leaves colour untouched where alpha is 0: nothing can be recovered there.
void premultiply(Image& image);
void unpremultiply(Image& image);

}  // namespace engine::capture
