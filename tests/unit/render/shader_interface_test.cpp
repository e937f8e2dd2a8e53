// SPDX-License-Identifier: MIT
// The uniform-block rule (shader_interface.hpp): members in list order then the textures'
// uniforms, std140 offsets (GLSL 4.50 §7.6.2.2), one declaration per name, a conflicting type
// refused, and a draw's parameters packed where the offsets say.
#include <cstddef>
#include <cstring>
#include <vector>

#include <gtest/gtest.h>

#include <glm/glm.hpp>

#include "engine/core/error.hpp"
#include "engine/render/shader_interface.hpp"

namespace {

using namespace engine::render;

struct Params {
    float f = 0.0f;
    glm::vec3 direction{0.0f, 0.0f, 2.0f};
    glm::vec2 v2{0.0f};
    bool flag = false;
    std::uint8_t byte = 0;
    glm::mat4 m{1.0f};
    TextureBinding base;
};

GlslProgram program() {
    GlslProgram p;
    p.uniforms = {{"u_f", UniformType::Float, offsetof(Params, f)},
                  {"u_dir", UniformType::Direction, offsetof(Params, direction)},
                  {"u_v2", UniformType::Vec2, offsetof(Params, v2)},
                  {"u_flag", UniformType::Bool, offsetof(Params, flag)},
                  {"u_byte", UniformType::Byte, offsetof(Params, byte)},
                  {"u_m", UniformType::Mat4, offsetof(Params, m)}};
    p.textures = {{"u_base", offsetof(Params, base), 0, TextureRead::Sampled, TextureUse::Sampled, true, "u_hasBase",
                   "u_filter", "u_premultiplied"}};
    return p;
}

TEST(ShaderInterface, Std140OffsetsInListOrder) {
    const UniformBlockLayout l = uniformBlockLayout("p", program());
    std::vector<std::string> names;
    std::vector<std::uint32_t> offsets;
    for (const UniformBlockMember& m : l.members) names.push_back(m.name), offsets.push_back(m.offset);
    EXPECT_EQ(names, (std::vector<std::string>{"u_f", "u_dir", "u_v2", "u_flag", "u_byte", "u_m", "u_hasBase",
                                               "u_filter", "u_premultiplied"}));
    // float 0; vec3 aligned to 16; vec2 at 28 rounded to 8 = 32; bool 40; int 44; mat4 at 48;
    // then bool 112, int 116, bool 120; the block rounded to 16.
    EXPECT_EQ(offsets, (std::vector<std::uint32_t>{0, 16, 32, 40, 44, 48, 112, 116, 120}));
    EXPECT_EQ(l.size, 128u);
}

TEST(ShaderInterface, DeclaresOnceAndRefusesAConflictingType) {
    GlslProgram p = program();
    p.uniforms.push_back({"u_f", UniformType::Float, 0});
    EXPECT_EQ(uniformBlockLayout("p", p).members.size(), 9u);
    p.uniforms.push_back({"u_f", UniformType::Vec4, 0});
    try {
        uniformBlockLayout("dup", p);
        FAIL() << "a conflicting type was accepted";
    } catch (const engine::Error& e) {
        EXPECT_NE(std::string(e.what()).find("program 'dup': uniform u_f is declared both float and vec4"),
                  std::string::npos)
            << e.what();
    }
}

TEST(ShaderInterface, DeclarationsPerDialect) {
    const UniformBlockLayout l = uniformBlockLayout("p", program());
    const std::string gl = uniformDeclarations(l, GlslDialect::OpenGl, 1, 0);
    const std::string vk = uniformDeclarations(l, GlslDialect::Vulkan, 1, 0);
    EXPECT_NE(gl.find("uniform vec3 u_dir;\n"), std::string::npos);
    EXPECT_NE(gl.find("uniform int u_byte;\n"), std::string::npos);
    EXPECT_EQ(vk.find("layout(std140, set = 1, binding = 0) uniform Params {\n"), 0u);
    EXPECT_NE(vk.find("    mat4 u_m;\n"), std::string::npos);
    EXPECT_EQ(uniformDeclarations({}, GlslDialect::Vulkan, 1, 0), "");
    EXPECT_NE(meshInterpolants(GlslDialect::Vulkan, false).find("layout(location = 3) flat in int v_instance;"),
              std::string::npos);
}

TEST(ShaderInterface, PacksWhereTheOffsetsSay) {
    const GlslProgram p = program();
    const UniformBlockLayout l = uniformBlockLayout("p", p);
    Params params;
    params.f = 1.5f;
    params.flag = true;
    params.byte = 7;
    params.m[3][2] = 9.0f;
    params.base.texture = {1, 1};
    params.base.sampler.filter = Filter::Bilinear;
    std::vector<std::byte> out(l.size);
    packUniformBlock(
        l, p, &params, [](TextureHandle) { return true; }, out);
    auto at = [&](std::uint32_t offset, auto value) {
        std::memcpy(&value, out.data() + offset, sizeof value);
        return value;
    };
    EXPECT_EQ(at(0, 0.0f), 1.5f);
    EXPECT_EQ(at(24, 0.0f), 1.0f);  // the direction normalised: (0, 0, 1)
    EXPECT_EQ(at(40, 0u), 1u);
    EXPECT_EQ(at(44, 0), 7);
    EXPECT_EQ(at(48 + 3 * 16 + 8, 0.0f), 9.0f);  // column 3, row 2
    EXPECT_EQ(at(112, 0u), 1u);                  // present
    EXPECT_EQ(at(116, 0), int(Filter::Bilinear));
    EXPECT_EQ(at(120, 0u), 1u);  // premultiplied
}

}  // namespace
