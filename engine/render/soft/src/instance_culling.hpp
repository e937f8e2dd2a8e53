// SPDX-License-Identifier: MIT
#pragma once
// Whole instances rejected before their vertex work: the box of a mesh's positions, taken
// through an instance's model-view-projection, lies beyond one clip plane, so every one of
// its triangles would be rejected by outsideOnePlane (triangle_setup.hpp) anyway.
#include <span>

#include <glm/glm.hpp>

#include "engine/render/vertex.hpp"
#include "engine/render/kernel/detail/triangle_setup.hpp"

namespace engine::render::soft {

// The object-space box of a vertex buffer's positions; `usable` is false for an empty
// buffer or one with a non-finite position (such meshes are never rejected whole).
struct PositionBounds {
    glm::dvec3 min{0.0}, max{0.0};
    bool usable = false;
};

PositionBounds positionBounds(std::span<const Vertex> vertices);

// Whether every point of `bounds` transformed by `mvp` (as the vertex stage does, in float)
// lies beyond one of the planes outsideOnePlane tests, with room for the float rounding of
// that transform, so that each triangle made of such points is rejected there too.
bool instanceOutsideOnePlane(const glm::mat4& mvp, const PositionBounds& bounds, const Viewport& viewport);

}  // namespace engine::render::soft
