// SPDX-License-Identifier: MIT
#pragma once
// The engine's one vertex layout and per-instance data. A fixed layout keeps every
// program kind implementable on every backend; meshes that lack an attribute fill it
// with its default (normal +Z, colour white).
#include <glm/glm.hpp>

namespace engine::render {

struct Vertex {
    glm::vec3 position{0.0f};
    glm::vec3 normal{0.0f, 0.0f, 1.0f};
    glm::vec2 uv{0.0f};
    glm::vec4 color{1.0f};
};
static_assert(sizeof(Vertex) == 48);

// One per drawn instance: hundreds of trees are one mesh and one draw ([Hathaway 2010] §3.3).
struct Instance {
    glm::mat4 model{1.0f};
    glm::vec4 tint{1.0f};  // multiplies the vertex colour
};
static_assert(sizeof(Instance) == 80);

}  // namespace engine::render
