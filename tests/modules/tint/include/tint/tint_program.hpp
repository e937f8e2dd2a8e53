// SPDX-License-Identifier: MIT
#pragma once
// The tint program: full screen, every pixel outputs `color`; the tint's pipeline multiplies
// the frame's colour by it. Described once for every backend: the GLSL in tint_program.cpp,
// the soft kernel in tint_kernel.hpp.
#include <glm/glm.hpp>

#include "engine/render/program_desc.hpp"

namespace tint {

struct TintParams {
    glm::vec3 color{1.0f};  // each channel in [0, 1]
};

// For Backend::createProgram. Draws are checked for a colour in [0, 1].
engine::render::ProgramDesc tintProgram();

}  // namespace tint
