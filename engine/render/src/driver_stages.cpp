// SPDX-License-Identifier: MIT
#include "engine/render/driver_stages.hpp"

#include <algorithm>

#include "engine/core/error.hpp"
#include "engine/render/glsl/standard_programs.hpp"
#include "engine/render/pipeline.hpp"
#include "engine_render_glsl.hpp"  // generated from glsl/

namespace engine::render {
namespace {

std::string versionLine(GlslDialect dialect) {
    // "core" is GL's profile word; withGlslVersion (the GL driver) lowers it to 4.30 on 4.3/4.4
    // contexts. Vulkan GLSL has no profile.
    return dialect == GlslDialect::OpenGl ? "#version 450 core\n" : "#version 450\n";
}

// The built-ins that GL_KHR_vulkan_glsl renamed; the stages below read them through these
// macros. gl_InstanceIndex counts from the draw's first instance where gl_InstanceID counts
// from 0: only v_instance's sign is read (the drivers' meshEntry), so both serve.
std::string indexNames(GlslDialect dialect) {
    return dialect == GlslDialect::OpenGl
               ? "#define VERTEX_INDEX gl_VertexID\n#define INSTANCE_INDEX gl_InstanceID\n"
               : "#define VERTEX_INDEX gl_VertexIndex\n#define INSTANCE_INDEX gl_InstanceIndex\n";
}

// The shared tail's inputs (glsl::kFinish lists them), in the order of Vulkan's push-constant
// range (TailConstants in the Vulkan driver: std430 offsets 0, 4, 8, 12, 16 and 32).
constexpr ShaderParameter kTailParameters[] = {
    {"int", "u_alphaSelect"}, {"int", "u_alphaFunc"}, {"float", "u_alphaRef"},
    {"int", "u_a2cSamples"},  {"int", "u_a2cActual"}, {"ivec4", "u_scissor"},
};

constexpr ShaderParameter kResolveParameters[] = {{"int", "u_samples"}, {"int", "u_greater"}};

std::string resolveHead(GlslDialect dialect) {
    const std::string sampler = dialect == GlslDialect::OpenGl ? "layout(binding = 0)" : "layout(set = 0, binding = 0)";
    return versionLine(dialect) + sampler + " uniform sampler2DMS u_source;\n" +
           parameterDeclarations(kResolveParameters, dialect, "Resolve");
}

std::string declarations(GlslDialect dialect, const UniformBlockLayout& layout) {
    return uniformDeclarations(layout, dialect, kVulkanUniformSet, 0);
}

}  // namespace

std::string vertexStage(GlslDialect dialect, VertexInput input, const std::string& programName,
                        const UniformBlockLayout& layout) {
    if (input == VertexInput::Fullscreen)
        return versionLine(dialect) + indexNames(dialect) + glsl::embedded::kFullscreenVertexMain;
    if (std::none_of(layout.members.begin(), layout.members.end(),
                     [](const UniformBlockMember& m) { return m.name == "u_viewProj" && m.type == UniformType::Mat4; }))
        throw Error("program '" + programName + "': a mesh program's uniforms need u_viewProj (mat4)");
    return versionLine(dialect) + indexNames(dialect) + declarations(dialect, layout) +
           meshInterpolants(dialect, true) + glsl::embedded::kMeshVertexMain;
}

std::string fragmentStage(GlslDialect dialect, VertexInput input, const UniformBlockLayout& layout,
                          const std::string& body, int colorTargets, std::string_view meshEntry) {
    std::string s = versionLine(dialect);
    const int outputs = dialect == GlslDialect::OpenGl ? kMaxColorTargets : colorTargets;
    for (int i = 0; i < kMaxColorTargets; ++i)
        s += (i < outputs ? "layout(location = " + std::to_string(i) + ") out vec4 o_color"
                          : std::string("vec4 o_color")) +
             std::to_string(i) + ";\n";
    s += parameterDeclarations(kTailParameters, dialect, "Tail") + glsl::kFinish;
    if (input == VertexInput::Mesh) s += meshInterpolants(dialect, false);
    s += declarations(dialect, layout);
    if (input != VertexInput::Mesh || meshEntry.empty()) return s + body;
    return s + "#define main programMain\n" + body + "\n#undef main\nvoid main() {\n" + std::string(meshEntry) +
           "    programMain();\n}\n";
}

std::string resolveColorStage(GlslDialect dialect) { return resolveHead(dialect) + glsl::embedded::kResolveColorMain; }
std::string resolveDepthStage(GlslDialect dialect) { return resolveHead(dialect) + glsl::embedded::kResolveDepthMain; }

}  // namespace engine::render
