// SPDX-License-Identifier: MIT
#pragma once
// The Vulkan GLSL of a program (the same body as on GL; the declarations from the shared rule,
// shader_interface.hpp, in the Vulkan dialect) and its SPIR-V from libshaderc, cached in memory
// by source, so a program compiled once in a process is never compiled again.
#include <cstdint>
#include <string>
#include <vector>

#include "engine/render/driver_stages.hpp"
#include "engine/render/program_desc.hpp"
#include "engine/render/shader_interface.hpp"

namespace engine::render::vk {

// The push constants of the shared fragment tail (glsl::kFinish's inputs), std430, in the order
// driver_stages.cpp declares them.
struct TailConstants {
    std::int32_t alphaSelect = 0;  // 0 all, 1 passing, 2 failing (FailModePlan)
    std::int32_t alphaFunc = 7;
    float alphaRef = 0.0f;
    std::int32_t a2cSamples = 0;
    std::int32_t a2cActual = 1;
    std::int32_t pad[3] = {};
    std::int32_t scissor[4] = {};
};
static_assert(sizeof(TailConstants) == 48);

// Descriptor sets (driver_stages.hpp): 0 holds the textures (binding = TextureField::unit), 1
// the uniform block.
inline constexpr int kTextureSet = kVulkanTextureSet;
inline constexpr int kUniformSet = kVulkanUniformSet;

std::string vertexSource(VertexInput input, const std::string& programName, const UniformBlockLayout& block);
// The fragment stage for a pass with `colorTargets` colour targets.
std::string fragmentSource(VertexInput input, const UniformBlockLayout& block, const std::string& body,
                           int colorTargets);
// The backend's own full-screen programs (resolves): complete fragment stages.
std::string resolveColorSource();
std::string resolveDepthSource();

enum class Stage : std::uint8_t { Vertex, Fragment };
// SPIR-V for Vulkan 1.3; throws engine::Error naming `program` and the stage, with shaderc's log.
std::vector<std::uint32_t> compileSpirv(const std::string& program, Stage stage, const std::string& source);

}  // namespace engine::render::vk
