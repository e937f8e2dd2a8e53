// SPDX-License-Identifier: MIT
#include "vk_shaders.hpp"

#include <map>
#include <mutex>

#include <shaderc/shaderc.h>

#include "engine/core/error.hpp"
#include "engine/render/glsl/standard_programs.hpp"
#include "engine/render/pipeline.hpp"

namespace engine::render::vk {
namespace {

// The GL backend's vertex stage (gl_shaders.cpp) in Vulkan GLSL: the same float operations in
// the same order under `precise`, so clip positions agree with the soft backend's bit for bit.
// gl_InstanceIndex replaces gl_InstanceID (it counts from the draw's first instance; only its
// sign is read, by the llvmpipe guard).
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
    v_instance = gl_InstanceIndex;
}
)";

constexpr const char* kFullscreenVertex = R"(#version 450
void main() {
    vec2 p = vec2(float((gl_VertexIndex & 1) << 2) - 1.0, float((gl_VertexIndex & 2) << 1) - 1.0);
    gl_Position = vec4(p, 0.0, 1.0);
}
)";

constexpr const char* kTailConstants = R"(
layout(push_constant) uniform Tail {
    int u_alphaSelect;
    int u_alphaFunc;
    float u_alphaRef;
    int u_a2cSamples;
    int u_a2cActual;
    ivec4 u_scissor;
};
)";

// The GL backend's resolves (gl_shaders.cpp), in Vulkan GLSL. Colour: the average of the
// samples in the linear domain (the fetch decodes sRGB, an sRGB target encodes), summed in
// sample order as the soft backend does.
constexpr const char* kResolveColor = R"(#version 450
layout(set = 0, binding = 0) uniform sampler2DMS u_source;
layout(push_constant) uniform Resolve { int u_samples; int u_greater; };
layout(location = 0) out vec4 o_color;
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    precise vec4 sum = vec4(0.0);
    for (int s = 0; s < u_samples; ++s) sum += texelFetch(u_source, p, s);
    precise vec4 average = sum / float(u_samples);
    o_color = average;
}
)";

// Depth: the sample closest to the observer under the depth function ([Hathaway 2010] §3.5.1),
// never an average.
constexpr const char* kResolveDepth = R"(#version 450
layout(set = 0, binding = 0) uniform sampler2DMS u_source;
layout(push_constant) uniform Resolve { int u_samples; int u_greater; };
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    float best = texelFetch(u_source, p, 0).r;
    for (int s = 1; s < u_samples; ++s) {
        float z = texelFetch(u_source, p, s).r;
        if (u_greater != 0 ? z > best : z < best) best = z;
    }
    gl_FragDepth = best;
}
)";

std::string block(const UniformBlockLayout& layout) {
    return uniformDeclarations(layout, GlslDialect::Vulkan, kUniformSet, 0);
}

}  // namespace

std::string vertexSource(VertexInput input, const UniformBlockLayout& layout) {
    if (input == VertexInput::Fullscreen) return kFullscreenVertex;
    return std::string("#version 450\n") + block(layout) + meshInterpolants(GlslDialect::Vulkan, true) +
           kMeshVertexMain;
}

std::string fragmentSource(VertexInput input, const UniformBlockLayout& layout, const std::string& body,
                           int colorTargets) {
    // finish() writes all four outputs (glsl::kFinish); those without a target are variables.
    std::string s = "#version 450\n";
    for (int i = 0; i < kMaxColorTargets; ++i)
        s += (i < colorTargets ? "layout(location = " + std::to_string(i) + ") out vec4 o_color"
                               : std::string("vec4 o_color")) +
             std::to_string(i) + ";\n";
    s += std::string(kTailConstants) + glsl::kFinish;
    if (input == VertexInput::Mesh) s += meshInterpolants(GlslDialect::Vulkan, false) + glsl::kMeshFragmentGuard;
    return s + block(layout) + body;
}

std::string resolveColorSource() { return kResolveColor; }
std::string resolveDepthSource() { return kResolveDepth; }

std::vector<std::uint32_t> compileSpirv(const std::string& program, Stage stage, const std::string& source) {
    static std::mutex mutex;
    static std::map<std::pair<Stage, std::string>, std::vector<std::uint32_t>> cache;
    {
        std::lock_guard lock(mutex);
        auto it = cache.find({stage, source});
        if (it != cache.end()) return it->second;
    }
    shaderc_compiler_t compiler = shaderc_compiler_initialize();
    shaderc_compile_options_t options = shaderc_compile_options_initialize();
    shaderc_compile_options_set_target_env(options, shaderc_target_env_vulkan, shaderc_env_version_vulkan_1_3);
    shaderc_compile_options_set_source_language(options, shaderc_source_language_glsl);
    // No optimisation: `precise` and the float operations' order are kept as written.
    shaderc_compile_options_set_optimization_level(options, shaderc_optimization_level_zero);
    const shaderc_shader_kind kind = stage == Stage::Vertex ? shaderc_vertex_shader : shaderc_fragment_shader;
    const char* stageName = stage == Stage::Vertex ? "vertex" : "fragment";
    shaderc_compilation_result_t result =
        shaderc_compile_into_spv(compiler, source.data(), source.size(), kind, program.c_str(), "main", options);
    const bool ok = result && shaderc_result_get_compilation_status(result) == shaderc_compilation_status_success;
    std::string log = result ? shaderc_result_get_error_message(result) : "shaderc returned nothing";
    std::vector<std::uint32_t> spirv;
    if (ok) {
        const auto* words = reinterpret_cast<const std::uint32_t*>(shaderc_result_get_bytes(result));
        spirv.assign(words, words + shaderc_result_get_length(result) / 4);
    }
    if (result) shaderc_result_release(result);
    shaderc_compile_options_release(options);
    shaderc_compiler_release(compiler);
    if (!ok) throw Error("Vulkan program '" + program + "': the " + stageName + " stage does not compile: " + log);
    std::lock_guard lock(mutex);
    cache.emplace(std::pair{stage, source}, spirv);
    return spirv;
}

}  // namespace engine::render::vk
