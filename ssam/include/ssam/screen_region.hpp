// SPDX-License-Identifier: MIT
#pragma once
// The part of the screen some foliage can touch, from world-space bounds. SSAM uses it to
// skip batches out of view and to scissor the composite to where foliage is (the
// composite's cost is then proportional to the foliage on screen, not the screen).
#include <optional>

#include <glm/glm.hpp>

#include "engine/render/raster_state.hpp"
#include "ssam/foliage.hpp"

namespace ssam {

// std::nullopt when the box is certainly outside the view volume; otherwise a pixel
// rectangle inside [0, width) x [0, height) that contains every pixel the box can cover
// (the whole screen when the box crosses the camera plane).
std::optional<engine::render::Rect> screenRegion(const Bounds& bounds, const glm::mat4& viewProj, int width,
                                                 int height);

// Smallest rectangle containing both; an empty rectangle is the identity.
engine::render::Rect unite(const engine::render::Rect& a, const engine::render::Rect& b);

}  // namespace ssam
