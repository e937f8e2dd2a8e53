// SPDX-License-Identifier: MIT
// The stages every GLSL driver puts around a program's body (driver_stages.hpp) are one source:
// the GL and Vulkan texts differ only where the APIs do (version line, built-in index names,
// how inputs are declared), a mesh program without u_viewProj is refused on both, and the
// drivers' own parameters follow the declaration rule.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "engine/core/error.hpp"
#include "engine/render/driver_stages.hpp"

namespace {

using namespace engine::render;

UniformBlockLayout meshLayout() {
    GlslProgram p;
    p.uniforms = {{"u_viewProj", UniformType::Mat4, 0}, {"u_color", UniformType::Vec4, 64}};
    return uniformBlockLayout("test", p);
}

// The text after the declarations: from the first line that neither API-specific part writes.
std::string after(const std::string& source, const std::string& marker) {
    const auto at = source.find(marker);
    return at == std::string::npos ? std::string() : source.substr(at);
}

TEST(DriverStages, MeshVertexStageIsOneSourceInTwoDialects) {
    const std::string gl = vertexStage(GlslDialect::OpenGl, VertexInput::Mesh, "test", meshLayout());
    const std::string vk = vertexStage(GlslDialect::Vulkan, VertexInput::Mesh, "test", meshLayout());
    EXPECT_EQ(gl.rfind("#version 450 core\n", 0), 0u);
    EXPECT_EQ(vk.rfind("#version 450\n", 0), 0u);
    EXPECT_NE(gl.find("#define INSTANCE_INDEX gl_InstanceID\n"), std::string::npos);
    EXPECT_NE(vk.find("#define INSTANCE_INDEX gl_InstanceIndex\n"), std::string::npos);
    EXPECT_NE(gl.find("uniform mat4 u_viewProj;"), std::string::npos);
    EXPECT_NE(vk.find("layout(std140, set = 1, binding = 0) uniform Params {"), std::string::npos);
    const std::string body = after(gl, "layout(location = 0) in vec3 a_position;");
    ASSERT_FALSE(body.empty());
    EXPECT_EQ(body, after(vk, "layout(location = 0) in vec3 a_position;"));
    EXPECT_NE(body.find("precise vec4 clip = xy + zw;"), std::string::npos);
}

TEST(DriverStages, AMeshProgramWithoutAMat4ViewProjIsRefusedOnEveryDialect) {
    GlslProgram missing, wrongType;
    missing.uniforms = {{"u_color", UniformType::Vec4, 0}};
    wrongType.uniforms = {{"u_viewProj", UniformType::Vec4, 0}};
    for (const GlslDialect dialect : {GlslDialect::OpenGl, GlslDialect::Vulkan})
        for (const GlslProgram* p : {&missing, &wrongType}) {
            try {
                (void)vertexStage(dialect, VertexInput::Mesh, "leafy", uniformBlockLayout("leafy", *p));
                ADD_FAILURE() << "accepted";
            } catch (const engine::Error& e) {
                EXPECT_NE(std::string(e.what()).find("program 'leafy'"), std::string::npos) << e.what();
                EXPECT_NE(std::string(e.what()).find("u_viewProj (mat4)"), std::string::npos) << e.what();
            }
        }
    // A full-screen program needs none.
    EXPECT_NO_THROW((void)vertexStage(GlslDialect::Vulkan, VertexInput::Fullscreen, "leafy", {}));
}

TEST(DriverStages, FragmentHeadDeclaresOutputsAndTheTailPerDialect) {
    const std::string gl = fragmentStage(GlslDialect::OpenGl, VertexInput::Mesh, meshLayout(), "BODY", 2);
    const std::string vk = fragmentStage(GlslDialect::Vulkan, VertexInput::Mesh, meshLayout(), "BODY", 2);
    // GL declares every output (unbound ones are dropped); Vulkan only the pass's targets.
    EXPECT_NE(gl.find("layout(location = 3) out vec4 o_color3;"), std::string::npos);
    EXPECT_NE(vk.find("layout(location = 1) out vec4 o_color1;"), std::string::npos);
    EXPECT_NE(vk.find("\nvec4 o_color2;"), std::string::npos);
    EXPECT_NE(gl.find("uniform ivec4 u_scissor;"), std::string::npos);
    EXPECT_NE(vk.find("layout(push_constant) uniform Tail {\n    int u_alphaSelect;"), std::string::npos);
    EXPECT_EQ(gl.substr(gl.size() - 4), "BODY");
    EXPECT_EQ(vk.substr(vk.size() - 4), "BODY");
    EXPECT_NE(vk.find("layout(location = 3) flat in int v_instance;"), std::string::npos);
}

// A driver's workaround runs first in a Mesh program's main(), in no program's body; a
// full-screen program's body is left as it is.
TEST(DriverStages, MeshEntryRunsBeforeTheBodysMain) {
    const std::string body = "void main() { finish(vec4(1.0)); }\n";
    const std::string entry = "    if (v_instance < 0) discard;\n";
    const std::string mesh = fragmentStage(GlslDialect::OpenGl, VertexInput::Mesh, meshLayout(), body, 1, entry);
    const std::size_t renamed = mesh.find("#define main programMain\n" + body);
    ASSERT_NE(renamed, std::string::npos) << mesh;
    EXPECT_EQ(mesh.substr(renamed + 25 + body.size()),
              "\n#undef main\nvoid main() {\n    if (v_instance < 0) discard;\n    programMain();\n}\n");
    const std::string fullscreen = fragmentStage(GlslDialect::Vulkan, VertexInput::Fullscreen, {}, body, 1, entry);
    EXPECT_EQ(fullscreen.find("programMain"), std::string::npos);
    EXPECT_EQ(fullscreen.substr(fullscreen.size() - body.size()), body);
}

TEST(DriverStages, ResolvesReadTheSameParametersOnEveryDialect) {
    for (const GlslDialect dialect : {GlslDialect::OpenGl, GlslDialect::Vulkan}) {
        const std::string depth = resolveDepthStage(dialect), color = resolveColorStage(dialect);
        EXPECT_NE(depth.find("u_greater != 0 ? z > best : z < best"), std::string::npos);
        EXPECT_NE(color.find("sum / float(u_samples)"), std::string::npos);
    }
    EXPECT_NE(resolveDepthStage(GlslDialect::OpenGl).find("uniform int u_greater;"), std::string::npos);
    EXPECT_NE(resolveDepthStage(GlslDialect::Vulkan).find("layout(push_constant) uniform Resolve {"),
              std::string::npos);
}

TEST(DriverStages, ParameterDeclarationsFollowTheRule) {
    const ShaderParameter params[] = {{"int", "u_a"}, {"ivec4", "u_b"}};
    EXPECT_EQ(parameterDeclarations(params, GlslDialect::OpenGl, "P"), "uniform int u_a;\nuniform ivec4 u_b;\n");
    EXPECT_EQ(parameterDeclarations(params, GlslDialect::Vulkan, "P"),
              "layout(push_constant) uniform P {\n    int u_a;\n    ivec4 u_b;\n};\n");
}

}  // namespace
