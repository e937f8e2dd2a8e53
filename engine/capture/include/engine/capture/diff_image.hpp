// SPDX-License-Identifier: MIT
#pragma once
// Difference images for looking at where two images disagree, as idiff -o -abs -scale writes them.
#include <filesystem>

#include "engine/capture/image.hpp"

namespace engine::capture {

// |a - b| * scale per value (NaN where either is NaN), with a's channel names.
// Throws engine::Error when the images differ in size or channel count.
Image absoluteDifference(const Image& a, const Image& b, float scale = 1.0f);

// Writes absoluteDifference(a, b, scale). The values are errors, not colours, so a PNG
// stores them without the sRGB curve (an error of 1/255 becomes code 1, as with idiff);
// an EXR stores them as float. Other extensions are an engine::Error.
void writeDiffImage(const std::filesystem::path& path, const Image& a, const Image& b, float scale = 1.0f);

}  // namespace engine::capture
