// SPDX-License-Identifier: MIT
#pragma once
// Writing captures. PNG for looking at (8-bit sRGB, straight alpha), EXR for exact values
// (linear, premultiplied, half or float). Failures throw engine::Error naming the file.
#include <filesystem>
#include <initializer_list>
#include <string_view>

#include "engine/capture/image.hpp"

namespace engine::capture {

enum class ExrPixelType { Half, Float };

// Linear float -> 8-bit sRGB PNG: colour encoded with the exact curve, alpha linear,
// clamped to [0,1], NaN written as 0, rounded to nearest; premultiplied input is
// un-premultiplied first because PNG stores straight alpha. 1 to 4 channels.
void writePng(const std::filesystem::path& path, const Image& image);

// Stored codes written as they are. A premultiplied Image8 with alpha is refused: PNG
// stores straight alpha and 8-bit premultiplied colour cannot be un-premultiplied exactly.
void writePng(const std::filesystem::path& path, const Image8& image);

// One EXR part, channels named as in the image. Straight input with alpha is premultiplied
// first, since EXR colour is premultiplied by convention.
void writeExr(const std::filesystem::path& path, const Image& image, ExrPixelType type = ExrPixelType::Float);

// By extension: .png -> writePng, .exr -> writeExr (float). Anything else is an error.
void writeImage(const std::filesystem::path& path, const Image& image);

// Every writer here writes whole or not at all: a temporary file beside `path`, renamed over
// it on success (engine/core/output_file.hpp), so a failure leaves no partial image.

// For a tool to call before any work: throws engine::Error (saying what would work) unless
// `path`'s extension is one of `extensions` (lower case, with the dot) and OpenImageIO has a
// writer for it. The directory is checked separately (engine::requireWritableFile).
void requireImageExtension(const std::filesystem::path& path,
                           std::initializer_list<std::string_view> extensions = {".png", ".exr"});

}  // namespace engine::capture
