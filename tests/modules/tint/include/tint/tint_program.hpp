// SPDX-License-Identifier: MIT
#pragma once
// The tint program: full screen, every pixel outputs `color`; the tint's pipeline multiplies
// the frame's colour by it. Described once for every backend: its parameter block below (the
// struct, the uniform table and the GLSL declarations come from it, param_block.hpp), the GLSL
// body in glsl/tint_fragment.glsl, the soft kernel in tint_kernel.hpp.
#include <glm/glm.hpp>

#include "engine/render/param_block.hpp"
#include "engine/render/program_desc.hpp"

namespace tint {

#define TINT_PARAMS(UNIFORM, DIRECTION, TEXTURE) UNIFORM(glm::vec3, color, glm::vec3(1.0f)) /* each channel in [0, 1] */
ENGINE_PARAM_BLOCK(TintParams, TINT_PARAMS);

// For Backend::createProgram. Draws are checked for a colour in [0, 1].
engine::render::ProgramDesc tintProgram();

}  // namespace tint
