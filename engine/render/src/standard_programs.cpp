#include "engine/render/standard_programs.hpp"

#include <cstddef>
#include <string>

#include "engine/core/error.hpp"

namespace engine::render {
namespace {

template <typename Params>
ProgramDesc describe(ProgramKind kind, VertexInput input, const char* paramsName) {
    ProgramDesc d;
    d.name = programKindName(kind);
    d.vertexInput = input;
    d.params = paramsType<Params>();
    d.paramsName = paramsName;
    return d;
}

std::uint32_t at(std::size_t offset) { return std::uint32_t(offset); }

// SurfaceParams and WboitAccumulateParams: the lit, textured surface's uniforms.
template <typename Params>
void litSurfaceLayout(GlslProgram& gl) {
    const std::size_t light = offsetof(Params, light);
    gl.uniforms = {
        {"u_viewProj", UniformType::Mat4, at(offsetof(Params, viewProj))},
        {"u_color", UniformType::Vec4, at(offsetof(Params, baseColorFactor))},
        {"u_towardLight", UniformType::Direction, at(light + offsetof(DirectionalLight, towardLight))},
        {"u_lightColor", UniformType::Vec3, at(light + offsetof(DirectionalLight, color))},
        {"u_ambient", UniformType::Vec3, at(light + offsetof(DirectionalLight, ambient))},
    };
    gl.textures = {{"u_baseColor", at(offsetof(Params, baseColor)), 0, TextureRead::Sampled, TextureUse::Sampled, true,
                    "u_hasTexture", "u_filter", "u_premultiplied"}};
}

ProgramDesc flat() {
    ProgramDesc d = describe<FlatParams>(ProgramKind::Flat, VertexInput::Mesh, "FlatParams");
    d.gl.uniforms = {{"u_viewProj", UniformType::Mat4, at(offsetof(FlatParams, viewProj))},
                     {"u_color", UniformType::Vec4, at(offsetof(FlatParams, color))}};
    return d;
}

ProgramDesc surface(ProgramKind kind) {
    ProgramDesc d = describe<SurfaceParams>(kind, VertexInput::Mesh, "SurfaceParams");
    litSurfaceLayout<SurfaceParams>(d.gl);
    return d;
}

ProgramDesc alphaOnly() {
    ProgramDesc d = describe<AlphaOnlyParams>(ProgramKind::AlphaOnly, VertexInput::Mesh, "AlphaOnlyParams");
    d.gl.uniforms = {{"u_viewProj", UniformType::Mat4, at(offsetof(AlphaOnlyParams, viewProj))},
                     {"u_alphaFactor", UniformType::Float, at(offsetof(AlphaOnlyParams, alphaFactor))}};
    d.gl.textures = {{"u_baseColor", at(offsetof(AlphaOnlyParams, baseColor)), 0, TextureRead::Sampled,
                      TextureUse::Sampled, true, "u_hasTexture", "u_filter"}};
    return d;
}

}  // namespace

ProgramDesc standardProgramDesc(ProgramKind kind) {
    switch (kind) {
        case ProgramKind::Flat: return flat();
        case ProgramKind::OpaqueLit:
        case ProgramKind::MaskedLit: return surface(kind);
        case ProgramKind::AlphaOnly: return alphaOnly();
    }
    throw Error("unknown standard program " + std::to_string(int(kind)));
}

}  // namespace engine::render
