// SPDX-License-Identifier: MIT
#pragma once
// Backend readbacks as capture images: what a render target holds, in linear light, ready
// for EXR layers, PNG captures and comparisons.
#include "engine/capture/image.hpp"
#include "engine/render/backend.hpp"

namespace engine::capture {

// Colour formats give RGBA (missing channels filled as GL does: 0, 0, 1), with sRGB targets
// decoded to linear; alpha is straight, as rendered. Depth gives one channel named "Z".
Image imageFromReadback(const render::Readback& readback);

}  // namespace engine::capture
