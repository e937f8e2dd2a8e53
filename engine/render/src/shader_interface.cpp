// SPDX-License-Identifier: MIT
#include "engine/render/shader_interface.hpp"

#include <algorithm>
#include <cstring>

#include <glm/glm.hpp>

#include "engine/core/error.hpp"

namespace engine::render {
namespace {

// std140 base alignment and size (GLSL 4.50 §7.6.2.2 rules 1-5): scalars 4, vec2 8, vec3 and
// vec4 16 (a vec3 occupies 12 bytes), a column-major mat4 four vec4 columns.
struct Std140 {
    std::uint32_t align, size;
};
Std140 std140(UniformType type) {
    switch (type) {
        case UniformType::Float:
        case UniformType::Int:
        case UniformType::Bool:
        case UniformType::Byte: return {4, 4};
        case UniformType::Vec2: return {8, 8};
        case UniformType::Vec3:
        case UniformType::Direction: return {16, 12};
        case UniformType::Vec4: return {16, 16};
        case UniformType::Mat4: return {16, 64};
    }
    return {4, 4};
}

template <typename T>
T readAt(const std::byte* at) {
    T value;
    std::memcpy(&value, at, sizeof value);
    return value;
}

template <typename T>
void writeAt(std::byte* at, const T& value) {
    std::memcpy(at, &value, sizeof value);
}

}  // namespace

const char* glslTypeName(UniformType type) {
    switch (type) {
        case UniformType::Float: return "float";
        case UniformType::Int:
        case UniformType::Byte: return "int";
        case UniformType::Bool: return "bool";
        case UniformType::Vec2: return "vec2";
        case UniformType::Vec3:
        case UniformType::Direction: return "vec3";
        case UniformType::Vec4: return "vec4";
        case UniformType::Mat4: return "mat4";
    }
    return "float";
}

UniformBlockLayout uniformBlockLayout(const std::string& programName, const GlslProgram& program) {
    UniformBlockLayout layout;
    std::uint32_t offset = 0;
    auto add = [&](const char* name, UniformType type, UniformBlockMember::Source source, std::size_t index) {
        for (const UniformBlockMember& m : layout.members)
            if (m.name == name) {
                if (glslTypeName(m.type) != std::string(glslTypeName(type)))
                    throw Error("program '" + programName + "': uniform " + name + " is declared both " +
                                glslTypeName(m.type) + " and " + glslTypeName(type));
                return;
            }
        const Std140 s = std140(type);
        offset = (offset + s.align - 1) / s.align * s.align;
        layout.members.push_back({name, type, offset, source, index});
        offset += s.size;
    };
    for (std::size_t i = 0; i < program.uniforms.size(); ++i)
        add(program.uniforms[i].name, program.uniforms[i].type, UniformBlockMember::Source::Field, i);
    for (std::size_t i = 0; i < program.textures.size(); ++i) {
        const TextureField& t = program.textures[i];
        if (t.presentUniform) add(t.presentUniform, UniformType::Bool, UniformBlockMember::Source::TexturePresent, i);
        if (t.filterUniform) add(t.filterUniform, UniformType::Int, UniformBlockMember::Source::TextureFilter, i);
        if (t.premultipliedUniform)
            add(t.premultipliedUniform, UniformType::Bool, UniformBlockMember::Source::TexturePremultiplied, i);
    }
    layout.size = layout.members.empty() ? 0 : (offset + 15) / 16 * 16;
    return layout;
}

std::string uniformDeclarations(const UniformBlockLayout& layout, GlslDialect dialect, int set, int binding,
                                const char* blockName) {
    std::string s;
    if (layout.empty()) return s;
    const bool block = dialect == GlslDialect::Vulkan;
    if (block)
        s += "layout(std140, set = " + std::to_string(set) + ", binding = " + std::to_string(binding) + ") uniform " +
             blockName + " {\n";
    for (const UniformBlockMember& m : layout.members)
        s += std::string(block ? "    " : "uniform ") + glslTypeName(m.type) + " " + m.name + ";\n";
    if (block) s += "};\n";
    return s;
}

std::string parameterDeclarations(std::span<const ShaderParameter> parameters, GlslDialect dialect,
                                  const char* blockName) {
    const bool block = dialect == GlslDialect::Vulkan;
    std::string s = block ? std::string("layout(push_constant) uniform ") + blockName + " {\n" : std::string();
    for (const ShaderParameter& p : parameters)
        s += std::string(block ? "    " : "uniform ") + p.glslType + " " + p.name + ";\n";
    return block ? s + "};\n" : s;
}

std::string samplerDeclarations(const GlslProgram& program) {
    std::vector<const TextureField*> byUnit;
    for (const TextureField& t : program.textures) byUnit.push_back(&t);
    std::stable_sort(byUnit.begin(), byUnit.end(),
                     [](const TextureField* a, const TextureField* b) { return a->unit < b->unit; });
    std::string s;
    for (const TextureField* t : byUnit)
        s += "layout(binding = " + std::to_string(t->unit) + ") uniform sampler2D " + t->name + ";\n";
    return s;
}

std::string meshInterpolants(GlslDialect dialect, bool vertexStage) {
    const char* dir = vertexStage ? "out" : "in";
    const bool vk = dialect == GlslDialect::Vulkan;
    auto line = [&](int location, const char* qualifiers, const char* type, const char* name) {
        return std::string(vk ? "layout(location = " + std::to_string(location) + ") " : std::string()) + qualifiers +
               dir + " " + type + " " + name + ";\n";
    };
    return line(0, "", "vec2", "v_uv") + line(1, "", "vec3", "v_normal") + line(2, "", "vec4", "v_color") +
           line(3, "flat ", "int", "v_instance");
}

void packUniformBlock(const UniformBlockLayout& layout, const GlslProgram& program, const void* params,
                      const std::function<bool(TextureHandle)>& premultiplied, std::span<std::byte> out) {
    if (out.size() < layout.size)
        throw Error("uniform block: " + std::to_string(out.size()) + " bytes given, " + std::to_string(layout.size) +
                    " needed");
    const auto* bytes = static_cast<const std::byte*>(params);
    for (const UniformBlockMember& m : layout.members) {
        std::byte* at = out.data() + m.offset;
        switch (m.source) {
            case UniformBlockMember::Source::Field: {
                const std::byte* from = bytes + program.uniforms[m.index].offset;
                switch (m.type) {
                    case UniformType::Float: writeAt(at, readAt<float>(from)); break;
                    case UniformType::Int: writeAt(at, readAt<std::int32_t>(from)); break;
                    case UniformType::Bool: writeAt(at, std::uint32_t(readAt<bool>(from) ? 1 : 0)); break;
                    case UniformType::Byte: writeAt(at, std::int32_t(readAt<std::uint8_t>(from))); break;
                    case UniformType::Vec2: writeAt(at, readAt<glm::vec2>(from)); break;
                    case UniformType::Vec3: writeAt(at, readAt<glm::vec3>(from)); break;
                    case UniformType::Direction: writeAt(at, glm::normalize(readAt<glm::vec3>(from))); break;
                    case UniformType::Vec4: writeAt(at, readAt<glm::vec4>(from)); break;
                    case UniformType::Mat4: writeAt(at, readAt<glm::mat4>(from)); break;
                }
                break;
            }
            case UniformBlockMember::Source::TexturePresent:
            case UniformBlockMember::Source::TextureFilter:
            case UniformBlockMember::Source::TexturePremultiplied: {
                const TextureField& t = program.textures[m.index];
                TextureHandle handle;
                Filter filter = Filter::Nearest;
                if (t.read == TextureRead::Sampled) {
                    const auto binding = readAt<TextureBinding>(bytes + t.offset);
                    handle = binding.texture;
                    filter = binding.sampler.filter;
                } else {
                    handle = readAt<TextureHandle>(bytes + t.offset);
                }
                std::uint32_t v = 0;
                if (m.source == UniformBlockMember::Source::TexturePresent) v = handle ? 1 : 0;
                else if (m.source == UniformBlockMember::Source::TextureFilter) v = std::uint32_t(filter);
                else v = handle && premultiplied(handle) ? 1 : 0;
                writeAt(at, v);
                break;
            }
        }
    }
}

}  // namespace engine::render
