// SPDX-License-Identifier: MIT
#pragma once
// Frame capture straight from render targets: several targets as named layers of one EXR
// (e.g. SSAM's opaque, depth, mask_max, mask_add, foliage, foliage_depth, result), or one
// target as an sRGB PNG.
#include <filesystem>
#include <span>
#include <string>

#include "engine/capture/image.hpp"
#include "engine/render/backend.hpp"

namespace engine::capture {

struct CapturedLayer {
    std::string name;
    Image image;
};

// Reads a target back as a layer (see imageFromReadback for the channel layout).
CapturedLayer captureTarget(render::Backend& backend, render::TextureHandle target, std::string name);

// One float EXR with a layer per entry; throws engine::Error naming the file on failure.
void writeLayersExr(const std::filesystem::path& path, std::span<const CapturedLayer> layers);

}  // namespace engine::capture
