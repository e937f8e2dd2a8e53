// SPDX-License-Identifier: MIT
#pragma once
// Several named images in one EXR file, the usual multi-layer convention: layer "depth"
// with channel Z becomes channel "depth.Z", layer "opaque" with RGBA becomes
// "opaque.R" ... "opaque.A". Tools such as oiiotool, Nuke and Blender show them as layers.
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "engine/capture/image.hpp"
#include "engine/capture/image_read.hpp"
#include "engine/capture/image_write.hpp"

namespace engine::capture {

struct Layer {
    std::string name;  // "" only for a single unprefixed layer (a plain EXR)
    const Image& image;
    ExrPixelType pixelType = ExrPixelType::Float;  // per layer: e.g. half colour, float depth
};

// All layers must share one size; names must be unique. Straight layers with alpha are
// premultiplied on the way out (EXR convention).
void writeExrLayers(const std::filesystem::path& path, const std::vector<Layer>& layers);

// Layer names in file order; channels without a "layer." prefix belong to layer "".
std::vector<std::string> listExrLayers(const std::filesystem::path& path, const ReadOptions& options = {});

// One layer, channel names without the prefix ("depth.Z" -> "Z"), premultiplied.
// A missing layer is an engine::Error listing the layers the file has.
Image readExrLayer(const std::filesystem::path& path, std::string_view layer, const ReadOptions& options = {});

}  // namespace engine::capture
