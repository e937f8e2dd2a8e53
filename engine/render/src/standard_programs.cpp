// SPDX-License-Identifier: MIT
#include "engine/render/standard_programs.hpp"

#include <cstddef>
#include <string>

#include "engine/core/error.hpp"

namespace engine::render {
namespace {

template <typename Params>
ProgramDesc describe(ProgramKind kind, VertexInput input, const char* paramsName) {
    return describeProgram<Params>(programKindName(kind), input, paramsName);
}

ProgramDesc flat() {
    ProgramDesc d = describe<FlatParams>(ProgramKind::Flat, VertexInput::Mesh, "FlatParams");
    d.gl.uniforms = {{"u_viewProj", UniformType::Mat4, offsetof(FlatParams, viewProj)},
                     {"u_color", UniformType::Vec4, offsetof(FlatParams, color)}};
    return d;
}

ProgramDesc surface(ProgramKind kind) {
    ProgramDesc d = describe<SurfaceParams>(kind, VertexInput::Mesh, "SurfaceParams");
    litSurfaceLayout<SurfaceParams>(d.gl);
    return d;
}

ProgramDesc alphaOnly() {
    ProgramDesc d = describe<AlphaOnlyParams>(ProgramKind::AlphaOnly, VertexInput::Mesh, "AlphaOnlyParams");
    d.gl.uniforms = {{"u_viewProj", UniformType::Mat4, offsetof(AlphaOnlyParams, viewProj)},
                     {"u_alphaFactor", UniformType::Float, offsetof(AlphaOnlyParams, alphaFactor)}};
    d.gl.textures = {{"u_baseColor", offsetof(AlphaOnlyParams, baseColor), 0, TextureRead::Sampled, TextureUse::Sampled,
                      true, "u_hasTexture", "u_filter"}};
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
