// SPDX-License-Identifier: MIT
#pragma once
// The GL driver's GLSL 4.50 stages (one source for every GLSL driver: driver_stages.hpp) in the
// GLSL ES 3.00 dialect: a translation of the preamble, never a second copy of a program.
#include <string>

#include "engine/render/program_desc.hpp"

namespace engine::render::gles {

// `source` as `#version 300 es`: highp defaults; `precise` (GLSL ES 3.20) dropped; no
// layout(binding = N) on samplers (ES 3.1), whose units the driver sets with glUniform1i
// (bindSamplerUnits); gl_SampleMask (ES 3.2) written to a variable nobody reads, the driver
// using GL_SAMPLE_ALPHA_TO_COVERAGE instead; textureQueryLevels(s) (GLSL 4.30, not in ES) read
// from a uniform the driver sets to the bound texture's levels (levelsUniform). Throws
// engine::Error naming `program` when the source is not a GLSL 4.50 stage. `remapClip` (vertex
// stages, on a context without EXT_clip_control) ends the stage with the clip position changed
// so that the window sees what the extension's upper-left origin and [0, 1] depth give, up to
// depth's rounding (why: gles_shaders.cpp).
std::string glslEs(std::string source, const std::string& program, bool remapClip = false);

// The uniform that stands for textureQueryLevels(sampler) in glslEs's translation.
std::string levelsUniform(const char* sampler);

// Sets each sampler of a linked program to its TextureField::unit (the program is left in use).
void bindSamplerUnits(unsigned int program, const GlslProgram& gl);

// The internal program that copies a depth texture's texels into a colour target (readback:
// ES 3.0 cannot glReadPixels a depth buffer).
std::string depthToColorFragmentSource();

}  // namespace engine::render::gles
