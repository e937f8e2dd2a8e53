// SPDX-License-Identifier: MIT
#include "gl_shaders.hpp"

#include "engine/render/glsl/standard_programs.hpp"

namespace engine::render::gl {
namespace {

// Vertex stage of every mesh program. Positions are computed with the soft backend's float
// operations in its order (glm: mvp = viewProj * model column by column, then
// (c0*x + c1*y) + (c2*z + c3*w)); `precise` forbids FMA contraction and reassociation, so
// the clip positions, and with them the snapped vertices, agree bit for bit.
constexpr const char* kMeshVertex = R"(#version 450 core
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec2 a_uv;
layout(location = 3) in vec4 a_color;
layout(location = 4) in vec4 a_model0;
layout(location = 5) in vec4 a_model1;
layout(location = 6) in vec4 a_model2;
layout(location = 7) in vec4 a_model3;
layout(location = 8) in vec4 a_tint;

uniform mat4 u_viewProj;

out vec2 v_uv;
out vec3 v_normal;
out vec4 v_color;
flat out int v_instance;  // see glsl::kMeshFragmentGuard

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
    v_instance = gl_InstanceID;
}
)";

// Full-screen programs: one triangle covering the viewport, no vertex input.
constexpr const char* kFullscreenVertex = R"(#version 450 core
void main() {
    vec2 p = vec2(float((gl_VertexID & 1) << 2) - 1.0, float((gl_VertexID & 2) << 1) - 1.0);
    gl_Position = vec4(p, 0.0, 1.0);
}
)";

// The GL declarations of the shared tail's inputs (glsl::kFinish lists them).
constexpr const char* kTailUniforms = R"(
uniform int u_alphaSelect;
uniform int u_alphaFunc;
uniform float u_alphaRef;
uniform int u_a2cSamples;
uniform int u_a2cActual;
uniform ivec4 u_scissor;
)";

// Colour resolve: the average of the samples in the linear domain (the fetch decodes sRGB,
// GL_FRAMEBUFFER_SRGB encodes the result), summed in sample order as the soft backend does.
constexpr const char* kResolveColorFragment = R"(#version 450 core
layout(binding = 0) uniform sampler2DMS u_source;
uniform int u_samples;
layout(location = 0) out vec4 o_color;
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    precise vec4 sum = vec4(0.0);
    for (int s = 0; s < u_samples; ++s) sum += texelFetch(u_source, p, s);
    precise vec4 average = sum / float(u_samples);
    o_color = average;
}
)";

// Depth resolve: the sample closest to the observer under the depth function ([Hathaway 2010]
// §3.5.1), never an average.
constexpr const char* kResolveDepthFragment = R"(#version 450 core
layout(binding = 0) uniform sampler2DMS u_source;
uniform int u_samples;
uniform bool u_greater;  // GREATER / GEQUAL: larger is closer (reverse-Z)
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    float best = texelFetch(u_source, p, 0).r;
    for (int s = 1; s < u_samples; ++s) {
        float z = texelFetch(u_source, p, s).r;
        if (u_greater ? z > best : z < best) best = z;
    }
    gl_FragDepth = best;
}
)";

}  // namespace

std::string vertexSource(VertexInput input) {
    return input == VertexInput::Fullscreen ? kFullscreenVertex : kMeshVertex;
}

std::string fragmentSource(VertexInput input, const UniformBlockLayout& layout, const std::string& body) {
    std::string s = std::string("#version 450 core\n") + glsl::kFragmentOutputs + kTailUniforms + glsl::kFinish;
    if (input == VertexInput::Mesh) s += meshInterpolants(GlslDialect::OpenGl, false) + glsl::kMeshFragmentGuard;
    return s + uniformDeclarations(layout, GlslDialect::OpenGl, 0, 0) + body;
}

std::string standardFragment(ProgramKind kind) { return glsl::standardFragmentBody(kind); }

std::string withGlslVersion(std::string source, int major, int minor) {
    if (major > 4 || (major == 4 && minor >= 5)) return source;
    const std::string from = "#version 450 core", to = "#version 430 core";  // 4.3/4.4 contexts
    if (source.compare(0, from.size(), from) == 0) source.replace(0, from.size(), to);
    return source;
}

std::string fullscreenVertexSource() { return kFullscreenVertex; }
std::string resolveColorFragmentSource() { return kResolveColorFragment; }
std::string resolveDepthFragmentSource() { return kResolveDepthFragment; }

}  // namespace engine::render::gl
