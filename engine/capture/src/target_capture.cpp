// SPDX-License-Identifier: MIT
#include "engine/capture/target_capture.hpp"

#include <vector>

#include "engine/capture/exr_layers.hpp"
#include "engine/capture/readback_image.hpp"

namespace engine::capture {

CapturedLayer captureTarget(render::Backend& backend, render::TextureHandle target, std::string name) {
    return {std::move(name), imageFromReadback(backend.readback(target))};
}

void writeLayersExr(const std::filesystem::path& path, std::span<const CapturedLayer> layers) {
    std::vector<Layer> exrLayers;
    exrLayers.reserve(layers.size());
    for (const CapturedLayer& l : layers) exrLayers.push_back({l.name, l.image, ExrPixelType::Float});
    writeExrLayers(path, exrLayers);
}

}  // namespace engine::capture
