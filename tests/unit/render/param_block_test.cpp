// SPDX-License-Identifier: MIT
// A parameter block declared once (param_block.hpp; the probe of tests/support/param_block_probe.hpp)
// gives a struct, a uniform and texture table and GLSL declarations that agree: each table
// entry names its member's GLSL name, its type follows the member's C++ type and its offset is
// where the member lies in the struct (measured here from the members' addresses, not with
// offsetof); the declarations of both dialects hold each uniform, the samplers each texture at
// its unit; packing a struct into the Vulkan block puts each member's value at its place; and the
// soft kernel draws what the body computes. The GL and Vulkan drivers compile and draw the same
// program (gl_param_block, vk_param_block).
#include <cstddef>
#include <cstring>
#include <iterator>
#include <string>
#include <type_traits>
#include <vector>

#include <gtest/gtest.h>

#include "engine/render/soft/soft_backend.hpp"
#include "param_block_probe.hpp"

namespace {

using namespace engine::render;
using ssam::testing::ProbeMode;
using ssam::testing::ProbeParams;

template <typename Params, typename Member>
std::size_t placeOf(const Params& p, const Member& member) {
    return std::size_t(reinterpret_cast<const std::byte*>(&member) - reinterpret_cast<const std::byte*>(&p));
}

struct ExpectedUniform {
    const char* name;
    UniformType type;
    std::size_t offset;
};

std::vector<ExpectedUniform> expectedUniforms() {
    const ProbeParams p;
    return {{"u_viewProj", UniformType::Mat4, placeOf(p, p.viewProj)},
            {"u_scale", UniformType::Float, placeOf(p, p.scale)},
            {"u_steps", UniformType::Int, placeOf(p, p.steps)},
            {"u_flipped", UniformType::Bool, placeOf(p, p.flipped)},
            {"u_mode", UniformType::Byte, placeOf(p, p.mode)},
            {"u_offset", UniformType::Vec2, placeOf(p, p.offset)},
            {"u_unused", UniformType::Vec3, placeOf(p, p.unused)},
            {"u_tint", UniformType::Vec4, placeOf(p, p.tint)},
            {"u_towardLight", UniformType::Direction, placeOf(p, p.towardLight)}};
}

void expectUniforms(const GlslProgram& gl, const std::vector<ExpectedUniform>& want) {
    ASSERT_EQ(gl.uniforms.size(), want.size());
    for (std::size_t i = 0; i < want.size(); ++i) {
        SCOPED_TRACE(want[i].name);
        EXPECT_STREQ(gl.uniforms[i].name, want[i].name);
        EXPECT_EQ(gl.uniforms[i].type, want[i].type);
        EXPECT_EQ(gl.uniforms[i].offset, want[i].offset);
    }
}

void expectTextures(const GlslProgram& gl, const std::vector<TextureField>& want) {
    auto same = [](const char* a, const char* b) { return a == b || (a && b && std::string(a) == b); };
    ASSERT_EQ(gl.textures.size(), want.size());
    for (std::size_t i = 0; i < want.size(); ++i) {
        const TextureField& t = gl.textures[i];
        SCOPED_TRACE(want[i].name);
        EXPECT_STREQ(t.name, want[i].name);
        EXPECT_EQ(t.offset, want[i].offset);
        EXPECT_EQ(t.unit, want[i].unit);
        EXPECT_EQ(t.read, want[i].read);
        EXPECT_EQ(t.use, want[i].use);
        EXPECT_EQ(t.optional, want[i].optional);
        EXPECT_TRUE(same(t.presentUniform, want[i].presentUniform));
        EXPECT_TRUE(same(t.filterUniform, want[i].filterUniform));
        EXPECT_TRUE(same(t.premultipliedUniform, want[i].premultipliedUniform));
    }
}

// A block on the engine's lit surface (ENGINE_PARAM_BLOCK_ON_LIT_SURFACE), as WBOIT's
// accumulation and SSAM's foliage depth declare theirs.
#define PARAM_BLOCK_TEST_ON_SURFACE(UNIFORM, DIRECTION, TEXTURE) \
    TEXTURE(mask, Texel, FullSize, Optional)                     \
    UNIFORM(float, threshold, 0.5f)
ENGINE_PARAM_BLOCK_ON_LIT_SURFACE(OnSurfaceParams, PARAM_BLOCK_TEST_ON_SURFACE);

TEST(ParamBlock, StructHasEachMemberWithItsTypeAndDefault) {
    static_assert(std::is_same_v<decltype(ProbeParams::viewProj), glm::mat4>);
    static_assert(std::is_same_v<decltype(ProbeParams::mode), ProbeMode>);
    static_assert(std::is_same_v<decltype(ProbeParams::towardLight), glm::vec3>);
    static_assert(std::is_same_v<decltype(ProbeParams::source), TextureHandle>);
    static_assert(std::is_same_v<decltype(ProbeParams::detail), TextureBinding>);
    static_assert(std::is_standard_layout_v<ProbeParams>);
    const ProbeParams p;
    EXPECT_EQ(p.viewProj, glm::mat4(1.0f));
    EXPECT_EQ(p.scale, 1.0f);
    EXPECT_EQ(p.towardLight, glm::vec3(0.0f, 1.0f, 0.0f));
    EXPECT_FALSE(p.source);
    EXPECT_FALSE(p.detail.texture);
}

TEST(ParamBlock, TableNamesTypesAndPlacesEachMember) {
    GlslProgram gl;
    ProbeParams::describe(gl);
    expectUniforms(gl, expectedUniforms());
    const ProbeParams p;
    expectTextures(gl, {
                           {"u_source", placeOf(p, p.source), 0, TextureRead::Texel, TextureUse::FullSize},
                           {"u_detail", placeOf(p, p.detail), 1, TextureRead::Sampled, TextureUse::Sampled, true,
                            "u_detailBound", "u_detailFilter", "u_detailPremultiplied"},
                       });
    // describeProgram() fills the same table.
    const ProgramDesc d = ssam::testing::probeProgram();
    ASSERT_EQ(d.gl.uniforms.size(), gl.uniforms.size());
    EXPECT_EQ(d.gl.textures.size(), gl.textures.size());
}

// The lit surface's members come first with their defaults and the surface's table
// (glsl/lit_surface.glsl's names, the light's members inside `light`, the base colour at unit 0),
// then the block's own members and entries, its textures from unit 1.
TEST(ParamBlock, ABlockOnTheLitSurfaceStartsWithTheSurface) {
    const OnSurfaceParams p;
    EXPECT_EQ(p.viewProj, glm::mat4(1.0f));
    EXPECT_EQ(p.baseColorFactor, glm::vec4(1.0f));
    EXPECT_FALSE(bool(p.baseColor.texture));
    EXPECT_FALSE(bool(p.mask));
    EXPECT_EQ(p.threshold, 0.5f);
    EXPECT_EQ(placeOf(p, p.viewProj), 0u);
    GlslProgram gl;
    OnSurfaceParams::describe(gl);
    expectUniforms(gl, {{"u_viewProj", UniformType::Mat4, placeOf(p, p.viewProj)},
                        {"u_color", UniformType::Vec4, placeOf(p, p.baseColorFactor)},
                        {"u_towardLight", UniformType::Direction, placeOf(p, p.light.towardLight)},
                        {"u_lightColor", UniformType::Vec3, placeOf(p, p.light.color)},
                        {"u_ambient", UniformType::Vec3, placeOf(p, p.light.ambient)},
                        {"u_threshold", UniformType::Float, placeOf(p, p.threshold)}});
    expectTextures(gl,
                   {{"u_baseColor", placeOf(p, p.baseColor), 0, TextureRead::Sampled, TextureUse::Sampled, true,
                     "u_hasTexture", "u_filter", "u_premultiplied"},
                    {"u_mask", placeOf(p, p.mask), 1, TextureRead::Texel, TextureUse::FullSize, true, "u_maskBound"}});
}

TEST(ParamBlock, DeclarationsHoldEveryMemberOnBothDialects) {
    const ProgramDesc d = ssam::testing::probeProgram();
    const UniformBlockLayout layout = uniformBlockLayout(d.name, d.gl);
    const std::string gl = uniformDeclarations(layout, GlslDialect::OpenGl, 1, 0);
    const std::string vk = uniformDeclarations(layout, GlslDialect::Vulkan, 1, 0);
    for (const ExpectedUniform& u : expectedUniforms()) {
        SCOPED_TRACE(u.name);
        const std::string member = std::string(glslTypeName(u.type)) + " " + u.name + ";\n";
        EXPECT_NE(gl.find("uniform " + member), std::string::npos) << gl;
        EXPECT_NE(vk.find("    " + member), std::string::npos) << vk;
    }
    for (const char* extra : {"bool u_detailBound;", "int u_detailFilter;", "bool u_detailPremultiplied;"}) {
        EXPECT_NE(gl.find(std::string("uniform ") + extra), std::string::npos) << gl;
        EXPECT_NE(vk.find(std::string("    ") + extra), std::string::npos) << vk;
    }
    EXPECT_EQ(samplerDeclarations(d.gl),
              "layout(binding = 0) uniform sampler2D u_source;\nlayout(binding = 1) uniform sampler2D u_detail;\n");
    EXPECT_EQ(d.gl.fragment.rfind(samplerDeclarations(d.gl), 0), 0u);
}

// The Vulkan block, packed from a struct whose every member differs from its default, holds
// each value where the layout puts it.
TEST(ParamBlock, PackedBlockCarriesEachMembersValue) {
    const ProgramDesc d = ssam::testing::probeProgram();
    const UniformBlockLayout layout = uniformBlockLayout(d.name, d.gl);
    const ProbeParams p = ssam::testing::probeValues();
    std::vector<std::byte> block(layout.size);
    packUniformBlock(
        layout, d.gl, &p, [](TextureHandle) { return false; }, block);
    auto member = [&](const char* name) -> const std::byte* {
        for (const UniformBlockMember& m : layout.members)
            if (m.name == name) return block.data() + m.offset;
        ADD_FAILURE() << name << " is not in the block";
        return block.data();
    };
    auto readFloat = [](const std::byte* at) {
        float v;
        std::memcpy(&v, at, sizeof v);
        return v;
    };
    auto readInt = [](const std::byte* at) {
        std::int32_t v;
        std::memcpy(&v, at, sizeof v);
        return v;
    };
    EXPECT_EQ(readFloat(member("u_viewProj") + 48), 0.0625f);  // column 3, row 0
    EXPECT_EQ(readFloat(member("u_scale")), 2.0f);
    EXPECT_EQ(readInt(member("u_steps")), 3);
    EXPECT_EQ(readInt(member("u_flipped")), 1);
    EXPECT_EQ(readInt(member("u_mode")), 2);
    EXPECT_EQ(readFloat(member("u_offset")), 0.125f);
    EXPECT_EQ(readFloat(member("u_offset") + 4), 7.0f);
    EXPECT_EQ(readFloat(member("u_tint") + 12), 0.5f);
    EXPECT_EQ(readFloat(member("u_towardLight") + 4), 1.0f);  // normalised
}

TEST(ParamBlock, SoftKernelDrawsWhatTheBodyComputes) {
    const auto soft = soft::createSoftBackend({1, 64, false});
    for (const bool withDetail : {false, true}) {
        SCOPED_TRACE(withDetail ? "with the detail texture" : "without it");
        const ProbeParams p = ssam::testing::probeValues();
        const Readback r = ssam::testing::drawProbe(*soft, p, withDetail);
        EXPECT_EQ(ssam::testing::probeMismatches(r, p, withDetail), 0);
        EXPECT_EQ(r.at(1, 1, 0), 2.0f * 5.0f / 8.0f + 0.0625f);  // pixel 5 of the source
    }
}

}  // namespace
