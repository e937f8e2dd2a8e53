// SPDX-License-Identifier: MIT
#pragma once
// GLSL of the engine's lit, textured surface, shared by its standard programs on the GL
// backend and by modules whose programs shade a surface the same way and then post-process
// the colour (program_desc.hpp: a module's GlslProgram::fragment may start with these). The
// text is engine/render/glsl/*.glsl, embedded at build time (standard_glsl.cpp).
namespace engine::render::glsl {

extern const char* const kBaseColorSampling;  // glsl/base_color_sampling.glsl

// The lit surface (OpaqueLit, MaskedLit; soft: kernel/programs.hpp SurfaceProgram). Defines
// main(). Before it: kBaseColorSampling and `#define ALPHA_MASKED 0` (opaque: alpha 1) or
// `1` (double-sided, alpha kept); a program that post-processes the masked colour defines
// SURFACE_OUTPUT(c) as a function of it (transparency's WBOIT accumulation does).
extern const char* const kLitSurface;  // glsl/lit_surface.glsl

}  // namespace engine::render::glsl
