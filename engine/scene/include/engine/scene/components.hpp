#pragma once
// Components the scene's systems and extraction work on.
#include "engine/scene/mesh_library.hpp"
#include "engine/scene/transform.hpp"

namespace engine::scene {

// Draws a model at the entity's Transform.
struct Renderable {
    ModelId model = 0;
};

// Pushes foliage away (modules/wind) and marks what the car is.
struct Collider {
    float radius = 1.0f;
};

}  // namespace engine::scene
