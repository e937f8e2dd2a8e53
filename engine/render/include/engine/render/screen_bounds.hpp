// SPDX-License-Identifier: MIT
#pragma once
// The part of the screen a bounding box can touch. Techniques use it to skip batches out of
// view and to scissor full-screen work to where the batches are (a composite then costs in
// proportion to what is on screen, not to the screen).
#include <optional>

#include <glm/glm.hpp>

#include "engine/render/masked_batch.hpp"
#include "engine/render/raster_state.hpp"

namespace engine::render {

// std::nullopt when the box is certainly outside the view volume; otherwise a pixel
// rectangle inside [0, width) x [0, height) that contains every pixel the box can cover
// (the whole screen when the box crosses the camera plane).
std::optional<Rect> screenBounds(const BoundingBox& bounds, const glm::mat4& viewProj, int width, int height);

// Smallest rectangle containing both; an empty rectangle is the identity.
Rect unite(const Rect& a, const Rect& b);

}  // namespace engine::render
