// SPDX-License-Identifier: MIT
#include "vk_shaders.hpp"

#include <map>
#include <mutex>

#include <shaderc/shaderc.h>

#include "engine/core/error.hpp"
#include "engine/render/driver_stages.hpp"

namespace engine::render::vk {

std::string vertexSource(VertexInput input, const std::string& programName, const UniformBlockLayout& layout) {
    return vertexStage(GlslDialect::Vulkan, input, programName, layout);
}

namespace {

// lavapipe sets triangles up with llvmpipe's code, rectangle fast path included (the GL driver's
// gl_shaders.cpp says what it breaks): a fragment shader reading a flat input skips it, so every
// Mesh program reads v_instance (never negative) first.
constexpr const char* kLavapipeFlatInput = "    if (v_instance < 0) discard;\n";

}  // namespace

std::string fragmentSource(VertexInput input, const UniformBlockLayout& layout, const std::string& body,
                           int colorTargets) {
    return fragmentStage(GlslDialect::Vulkan, input, layout, body, colorTargets, kLavapipeFlatInput);
}

std::string resolveColorSource() { return resolveColorStage(GlslDialect::Vulkan); }
std::string resolveDepthSource() { return resolveDepthStage(GlslDialect::Vulkan); }

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
