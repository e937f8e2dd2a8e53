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

ProgramDesc flat() { return describe<FlatParams>(ProgramKind::Flat, VertexInput::Mesh, "FlatParams"); }

ProgramDesc surface(ProgramKind kind) { return describe<SurfaceParams>(kind, VertexInput::Mesh, "SurfaceParams"); }

ProgramDesc alphaOnly() {
    ProgramDesc d = describe<AlphaOnlyParams>(ProgramKind::AlphaOnly, VertexInput::Mesh, "AlphaOnlyParams");
    // The shared sampling (glsl/base_color_sampling.glsl) reads the lit surface's names, and this
    // program ignores premultiplication (it outputs alpha alone).
    TextureField& baseColor = d.gl.textures.at(0);
    baseColor.presentUniform = "u_hasTexture";
    baseColor.filterUniform = "u_filter";
    baseColor.premultipliedUniform = nullptr;
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
