// SPDX-License-Identifier: MIT
#pragma once
// What a soft program's shade() receives (program_kernel.hpp), and how it says which of the
// interpolants it reads.
#include <glm/glm.hpp>

#include "sampler.hpp"

namespace engine::render::soft {

// What the rasterizer hands a program for one pixel (interpolated at its centre).
struct Fragment {
    int x = 0, y = 0;
    glm::vec2 uv{0.0f};
    UvDerivatives duv;
    glm::vec3 normal{0.0f, 0.0f, 1.0f};
    glm::vec4 color{1.0f};
    float clipW = 1.0f;  // clip-space w (the view depth under a perspective projection); set with uv/normal/color
    bool frontFacing = true;
};

struct ProgramNeeds {
    bool uv = false;
    bool derivatives = false;
    bool normal = false;
    bool color = false;       // the vertex colour
    bool colorAlpha = false;  // only its alpha (Fragment::color keeps 1 in r, g, b)
    constexpr bool anyAttribute() const { return uv || normal || color || colorAlpha; }
};

}  // namespace engine::render::soft
