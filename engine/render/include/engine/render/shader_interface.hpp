// SPDX-License-Identifier: MIT
#pragma once
// The one rule that turns a program's layout (GlslProgram::uniforms and ::textures) into the
// declarations its GLSL body reads, for every GLSL-consuming backend. A body declares neither
// its uniforms nor its interpolants; the driver puts these declarations before it:
//   - the parameter block: each UniformField in list order, then each texture's
//     presentUniform (bool), filterUniform (int) and premultipliedUniform (bool), a name given
//     twice declared once. GL declares them as loose uniforms (the default block, set by
//     glProgramUniform*); Vulkan GLSL forbids loose uniforms, so Vulkan declares the same
//     members, in the same order, as one std140 block (GLSL 4.50 §4.4.5, "std140") that the
//     driver fills with packUniformBlock;
//   - the interpolants of a Mesh program (v_uv, v_normal, v_color, and the flat v_instance),
//     with explicit locations on Vulkan, which has no matching by name.
// Samplers stay in the body (`layout(binding = unit) uniform sampler2D name;`), valid on both.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "engine/render/program_desc.hpp"

namespace engine::render {

enum class GlslDialect : std::uint8_t { OpenGl, Vulkan };

struct UniformBlockMember {
    std::string name;
    UniformType type = UniformType::Float;
    std::uint32_t offset = 0;  // std140 offset in the block
    enum class Source : std::uint8_t { Field, TexturePresent, TextureFilter, TexturePremultiplied };
    Source source = Source::Field;
    std::size_t index = 0;  // into GlslProgram::uniforms (Field) or ::textures
};

struct UniformBlockLayout {
    std::vector<UniformBlockMember> members;
    std::uint32_t size = 0;  // bytes, a multiple of 16 (std140 block size); 0 when empty
    bool empty() const { return members.empty(); }
};

// The block's members and their std140 offsets. Throws engine::Error naming the program when
// one name is given two different types.
UniformBlockLayout uniformBlockLayout(const std::string& programName, const GlslProgram& program);

// The GLSL type a member is declared with (Byte and Int: int, Direction: vec3).
const char* glslTypeName(UniformType type);

// The declarations as GLSL text. Vulkan: `layout(std140, set = S, binding = B) uniform
// <blockName> { ... };`, nothing when the layout is empty; GL: loose uniforms.
std::string uniformDeclarations(const UniformBlockLayout& layout, GlslDialect dialect, int set, int binding,
                                const char* blockName = "Params");

// A driver's own parameters (the shared tail's, a resolve's), declared by the same rule: GL
// loose uniforms; Vulkan one push-constant block named `blockName` (members in list order,
// std430: the driver's C++ struct of push constants follows this order).
struct ShaderParameter {
    const char* glslType;
    const char* name;
};
std::string parameterDeclarations(std::span<const ShaderParameter> parameters, GlslDialect dialect,
                                  const char* blockName);

// The samplers of a program's textures as its GLSL body declares them (`layout(binding = unit)
// uniform sampler2D name;`, valid on GL and on Vulkan's texture set 0), in unit order: for a
// body whose textures come from a parameter block (param_block.hpp), written nowhere else.
std::string samplerDeclarations(const GlslProgram& program);

// A Mesh program's interpolants, as the driver's vertex stage writes them (`out`, vertex) or
// the fragment stage reads them (`in`).
std::string meshInterpolants(GlslDialect dialect, bool vertexStage);

// A draw's parameters packed into the block (`out` has layout.size bytes). Direction members
// are normalised as glm::normalize does on the CPU; `premultiplied` says whether a texture
// is (for TexturePremultiplied members).
void packUniformBlock(const UniformBlockLayout& layout, const GlslProgram& program, const void* params,
                      const std::function<bool(TextureHandle)>& premultiplied, std::span<std::byte> out);

}  // namespace engine::render
