// SPDX-License-Identifier: MIT
#pragma once
// GLSL shared by every GLSL-consuming driver (GL, Vulkan): the fragment tail every program
// ends in (finish()) and the standard programs' bodies (what kernel/programs.hpp computes, line
// for line), kept in engine/render/glsl/*.glsl and embedded at build time (standard_glsl.cpp).
// Bodies declare no uniforms and no interpolants: the driver declares them from the program's
// layout (shader_interface.hpp).
#include <string>

#include "engine/render/glsl/lit_surface.hpp"
#include "engine/render/program.hpp"

namespace engine::render::glsl {

// The tail's inputs, which the driver declares (driver_stages.cpp; GL: loose uniforms, Vulkan:
// push constants):
//   int u_alphaSelect   0 all fragments, 1 those passing the alpha test, 2 those failing it
//   int u_alphaFunc     CompareFunc
//   float u_alphaRef
//   int u_a2cSamples    samples of the target as created (0: alpha-to-coverage off)
//   int u_a2cActual     samples the API really allocated (llvmpipe GL turns 2 into 4)
//   ivec4 u_scissor     x0, y0, x1, y1 of the draw's scissor; x1 = 0: not checked here
// Alpha-to-coverage with the soft backend's rule, the GS alpha test as a fragment selection,
// and the colour broadcast to every bound target.
extern const char* const kFinish;  // glsl/finish.glsl

// The fragment body of a standard program (standard_programs.hpp): glsl/flat_fragment.glsl,
// alpha_only_fragment.glsl, or the lit surface (lit_surface.hpp).
std::string standardFragmentBody(ProgramKind kind);

}  // namespace engine::render::glsl
