#pragma once
// GLSL 4.50 sources of every program kind (what soft/src/programs.hpp computes, line for
// line) and of the backend's internal programs (resolves).
#include <string>

#include "engine/render/program.hpp"

namespace engine::render::gl {

// Uniform/attribute/texture-unit layout shared by the sources and the backend.
enum TextureUnit : int { kUnitBaseColor = 0, kUnitFoliage = 0, kUnitMask = 1, kUnitMaskAdd = 2 };

// Fragment selection by the alpha test (u_alphaSelect), see FailModePlan.
enum AlphaSelect : int { kSelectAll = 0, kSelectPassing = 1, kSelectFailing = 2 };

std::string vertexSource(ProgramKind kind);
std::string fragmentSource(ProgramKind kind);

// The sources are GLSL 4.50; on a 4.3/4.4 context (a GLFW window where nothing newer exists)
// they are compiled as 4.30, which has everything they use.
std::string withGlslVersion(std::string source, int major, int minor);

std::string fullscreenVertexSource();
std::string resolveColorFragmentSource();
std::string resolveDepthFragmentSource();

}  // namespace engine::render::gl
