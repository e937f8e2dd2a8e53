// SPDX-License-Identifier: MIT
#pragma once
// GLSL 4.50 sources of the standard programs (what kernel/programs.hpp computes, line for
// line) and of the backend's internal programs (resolves), in the GL dialect of driver_stages.hpp.
#include <string>

#include "engine/render/program.hpp"
#include "engine/render/program_desc.hpp"
#include "engine/render/shader_interface.hpp"

namespace engine::render::gl {

// Fragment selection by the alpha test (u_alphaSelect), see FailModePlan.
enum AlphaSelect : int { kSelectAll = 0, kSelectPassing = 1, kSelectFailing = 2 };

// The vertex stage for a program's input, and its fragment stage: the shared head (outputs,
// finish(), the interpolants) and the layout's uniforms before the body, in the GL dialect of
// the one source every GLSL driver uses (driver_stages.hpp).
std::string vertexSource(VertexInput input, const std::string& programName, const UniformBlockLayout& layout);
std::string fragmentSource(VertexInput input, const UniformBlockLayout& layout, const std::string& body);
// The fragment body of a standard program (standard_programs.hpp).
std::string standardFragment(ProgramKind kind);

// The sources are GLSL 4.50; on a 4.3/4.4 context (a GLFW window where nothing newer exists)
// they are compiled as 4.30, which has everything they use.
std::string withGlslVersion(std::string source, int major, int minor);

std::string fullscreenVertexSource();
std::string resolveColorFragmentSource();
std::string resolveDepthFragmentSource();

}  // namespace engine::render::gl
