// SPDX-License-Identifier: MIT
#include "engine/render/driver_stages.hpp"

#include <algorithm>

#include "engine/core/error.hpp"
#include "engine/render/glsl/standard_programs.hpp"
#include "engine/render/pipeline.hpp"

namespace engine::render {
namespace {

std::string versionLine(GlslDialect dialect) {
    // "core" is GL's profile word; withGlslVersion (the GL driver) lowers it to 4.30 on 4.3/4.4
    // contexts. Vulkan GLSL has no profile.
    return dialect == GlslDialect::OpenGl ? "#version 450 core\n" : "#version 450\n";
}

// The built-ins that GL_KHR_vulkan_glsl renamed; the stages below read them through these
// macros. gl_InstanceIndex counts from the draw's first instance where gl_InstanceID counts
// from 0: only v_instance's sign is read (kMeshFragmentGuard), so both serve.
std::string indexNames(GlslDialect dialect) {
    return dialect == GlslDialect::OpenGl
               ? "#define VERTEX_INDEX gl_VertexID\n#define INSTANCE_INDEX gl_InstanceID\n"
               : "#define VERTEX_INDEX gl_VertexIndex\n#define INSTANCE_INDEX gl_InstanceIndex\n";
}

// Positions are computed with the soft backend's float operations in its order (glm: mvp =
// viewProj * model column by column, then (c0*x + c1*y) + (c2*z + c3*w)); `precise` forbids FMA
// contraction and reassociation, so the clip positions, and with them the snapped vertices,
// agree bit for bit.
constexpr const char* kMeshVertexMain = R"(
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec2 a_uv;
layout(location = 3) in vec4 a_color;
layout(location = 4) in vec4 a_model0;
layout(location = 5) in vec4 a_model1;
layout(location = 6) in vec4 a_model2;
layout(location = 7) in vec4 a_model3;
layout(location = 8) in vec4 a_tint;

vec4 mulColumn(mat4 a, vec4 b) {
    precise vec4 r = a[0] * b.x + a[1] * b.y + a[2] * b.z + a[3] * b.w;
    return r;
}

void main() {
    mat4 model = mat4(a_model0, a_model1, a_model2, a_model3);
    mat4 mvp = mat4(mulColumn(u_viewProj, model[0]), mulColumn(u_viewProj, model[1]),
                    mulColumn(u_viewProj, model[2]), mulColumn(u_viewProj, model[3]));
    precise vec4 xy = mvp[0] * a_position.x + mvp[1] * a_position.y;
    precise vec4 zw = mvp[2] * a_position.z + mvp[3];
    precise vec4 clip = xy + zw;
    gl_Position = clip;
    v_uv = a_uv;
    v_normal = mat3(model) * a_normal;
    v_color = a_color * a_tint;
    v_instance = INSTANCE_INDEX;
}
)";

// One triangle covering the viewport, no vertex input.
constexpr const char* kFullscreenVertexMain = R"(
void main() {
    vec2 p = vec2(float((VERTEX_INDEX & 1) << 2) - 1.0, float((VERTEX_INDEX & 2) << 1) - 1.0);
    gl_Position = vec4(p, 0.0, 1.0);
}
)";

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

constexpr const char* kResolveColorMain = R"(layout(location = 0) out vec4 o_color;
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    precise vec4 sum = vec4(0.0);
    for (int s = 0; s < u_samples; ++s) sum += texelFetch(u_source, p, s);
    precise vec4 average = sum / float(u_samples);
    o_color = average;
}
)";

constexpr const char* kResolveDepthMain = R"(void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    float best = texelFetch(u_source, p, 0).r;
    for (int s = 1; s < u_samples; ++s) {
        float z = texelFetch(u_source, p, s).r;
        if (u_greater != 0 ? z > best : z < best) best = z;
    }
    gl_FragDepth = best;
}
)";

std::string declarations(GlslDialect dialect, const UniformBlockLayout& layout) {
    return uniformDeclarations(layout, dialect, kVulkanUniformSet, 0);
}

}  // namespace

std::string vertexStage(GlslDialect dialect, VertexInput input, const std::string& programName,
                        const UniformBlockLayout& layout) {
    if (input == VertexInput::Fullscreen) return versionLine(dialect) + indexNames(dialect) + kFullscreenVertexMain;
    if (std::none_of(layout.members.begin(), layout.members.end(),
                     [](const UniformBlockMember& m) { return m.name == "u_viewProj" && m.type == UniformType::Mat4; }))
        throw Error("program '" + programName + "': a mesh program's uniforms need u_viewProj (mat4)");
    return versionLine(dialect) + indexNames(dialect) + declarations(dialect, layout) +
           meshInterpolants(dialect, true) + kMeshVertexMain;
}

std::string fragmentStage(GlslDialect dialect, VertexInput input, const UniformBlockLayout& layout,
                          const std::string& body, int colorTargets) {
    std::string s = versionLine(dialect);
    const int outputs = dialect == GlslDialect::OpenGl ? kMaxColorTargets : colorTargets;
    for (int i = 0; i < kMaxColorTargets; ++i)
        s += (i < outputs ? "layout(location = " + std::to_string(i) + ") out vec4 o_color"
                          : std::string("vec4 o_color")) +
             std::to_string(i) + ";\n";
    s += parameterDeclarations(kTailParameters, dialect, "Tail") + glsl::kFinish;
    if (input == VertexInput::Mesh) s += meshInterpolants(dialect, false) + glsl::kMeshFragmentGuard;
    return s + declarations(dialect, layout) + body;
}

std::string resolveColorStage(GlslDialect dialect) { return resolveHead(dialect) + kResolveColorMain; }
std::string resolveDepthStage(GlslDialect dialect) { return resolveHead(dialect) + kResolveDepthMain; }

}  // namespace engine::render
