// SPDX-License-Identifier: MIT
#include "gl_shaders.hpp"

#include "engine/render/driver_stages.hpp"
#include "engine/render/glsl/standard_programs.hpp"
#include "engine/render/pipeline.hpp"

namespace engine::render::gl {

std::string vertexSource(VertexInput input, const std::string& programName, const UniformBlockLayout& layout) {
    return vertexStage(GlslDialect::OpenGl, input, programName, layout);
}

namespace {

// llvmpipe (Mesa 22.x) has a fast path for non-indexed draws of exactly three triangles whose
// last one has zero area (lp_setup_analyse_triangles, meant for one Windows compositor's
// rectangles) that draws nothing at all unless the pattern is that rectangle; it is skipped when
// the fragment shader reads a flat ("constant") input. Every Mesh program reads v_instance first:
// never negative, so nothing is discarded.
constexpr const char* kLlvmpipeFlatInput = "    if (v_instance < 0) discard;\n";

}  // namespace

std::string fragmentSource(VertexInput input, const UniformBlockLayout& layout, const std::string& body) {
    return fragmentStage(GlslDialect::OpenGl, input, layout, body, kMaxColorTargets, kLlvmpipeFlatInput);
}

std::string standardFragment(ProgramKind kind) { return glsl::standardFragmentBody(kind); }

std::string withGlslVersion(std::string source, int major, int minor) {
    if (major > 4 || (major == 4 && minor >= 5)) return source;
    const std::string from = "#version 450 core", to = "#version 430 core";  // 4.3/4.4 contexts
    if (source.compare(0, from.size(), from) == 0) source.replace(0, from.size(), to);
    return source;
}

std::string fullscreenVertexSource() { return vertexStage(GlslDialect::OpenGl, VertexInput::Fullscreen, "", {}); }
std::string resolveColorFragmentSource() { return resolveColorStage(GlslDialect::OpenGl); }
std::string resolveDepthFragmentSource() { return resolveDepthStage(GlslDialect::OpenGl); }

}  // namespace engine::render::gl
