// SPDX-License-Identifier: MIT
#pragma once
// Small PNG pictures of captured layers, for the README's walk through SSAM's passes:
// colour layers as they are, masks as grey, reverse-Z depth as log distance (white near,
// black at the far plane) since raw reverse-Z depth is almost all near zero.
#include "engine/capture/target_capture.hpp"

namespace racer {

// The picture of one layer: 3 channels, linear light, ready for capture::writePng.
engine::capture::Image layerPicture(const engine::capture::CapturedLayer& layer, float nearPlane, float farPlane);

}  // namespace racer
