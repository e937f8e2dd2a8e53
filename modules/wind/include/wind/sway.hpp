// SPDX-License-Identifier: MIT
#pragma once
// The deformation of one plant's vertices for one frame, a pure function of the rest pose,
// the plant's pose and the time (so it is deterministic for a fixed time step and any
// thread count). [Hathaway 2010] §3.3: wind and collisions move the intersecting cards of a tree,
// and of neighbouring trees, unpredictably; SSAM does not care about their order.
#include <span>

#include <glm/glm.hpp>

#include "engine/render/vertex.hpp"
#include "engine/scene/bounds.hpp"
#include "wind/wind.hpp"

namespace wind {

struct SphereCollider {
    glm::vec3 center{0.0f};
    float radius = 0.0f;
};

// One plant this frame.
struct PlantPose {
    glm::mat4 model{1.0f};
    glm::mat4 inverseModel{1.0f};
    float baseY = 0.0f;   // model-space height of the plant's foot ...
    float height = 1.0f;  // ... and its extent: sway grows with (height above foot)^2
    Sway sway;
    // How much of the wind's bend and flutter the plant shows: 1 near, easing to 0 where it
    // leaves its full model (restWeight(), wind_system.hpp); collisions push regardless.
    float weight = 1.0f;
};

// The horizontal displacement of the plant's top this frame (world space): a slow sway
// with a small cross-wind component, plus gusts that travel downwind (trees downwind bend
// later). Zero for a rigid plant.
glm::vec3 bendAtTop(const Wind& wind, const PlantPose& plant, float time);

// Writes `out` (same size as `rest`) from `rest`: bend weighted by height^2, leaf flutter
// along the card normal when `flutter`, then every collider pushes vertices out of its
// sphere (plus Wind::colliderMargin); `push` (world space, per vertex) carries the push
// from frame to frame and relaxes towards rest by `decay` (exp(-springRate dt)) first.
// Returns the model-space bounds of `out`.
engine::scene::Aabb deformVertices(std::span<const engine::render::Vertex> rest, std::span<engine::render::Vertex> out,
                                   std::span<glm::vec3> push, const Wind& wind, const PlantPose& plant, float time,
                                   bool flutter, float decay, std::span<const SphereCollider> colliders);

}  // namespace wind
