#pragma once
// Small PNG pictures of captured layers, for the README's walk through SSAM's passes:
// colour layers as they are, masks as grey, reverse-Z depth as log distance (white near,
// black at the far plane) since raw reverse-Z depth is almost all near zero.
#include <filesystem>
#include <span>

#include "engine/capture/target_capture.hpp"

namespace racer {

// Writes <directory>/<prefix><layer>.png for every layer; returns how many were written.
int writeLayerPictures(const std::filesystem::path& directory, const std::string& prefix,
                       std::span<const engine::capture::CapturedLayer> layers, float nearPlane, float farPlane);

}  // namespace racer
