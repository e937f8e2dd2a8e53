// SPDX-License-Identifier: MIT
// FoliageMotion's description (transparency/temporal.hpp; soft: foliage_motion_kernel.hpp):
// AlphaOnly's parameters and uniforms, its own fragment body.
#include <cstddef>
#include <string>

#include "engine/render/glsl/lit_surface.hpp"
#include "engine/render/kernel/program_kernel.hpp"
#include "foliage_motion_kernel.hpp"
#include "transparency_glsl.hpp"  // generated from glsl/
#include "transparency/temporal.hpp"

namespace transparency {

using namespace engine::render;

ProgramDesc foliageMotionProgram() {
    ProgramDesc d = describeProgram<AlphaOnlyParams>("FoliageMotion", VertexInput::Mesh, "AlphaOnlyParams");
    d.gl.uniforms = {{"u_viewProj", UniformType::Mat4, offsetof(AlphaOnlyParams, viewProj)},
                     {"u_alphaFactor", UniformType::Float, offsetof(AlphaOnlyParams, alphaFactor)}};
    d.gl.textures = {{"u_baseColor", offsetof(AlphaOnlyParams, baseColor), 0, TextureRead::Sampled, TextureUse::Sampled,
                      true, "u_hasTexture", "u_filter"}};
    d.gl.fragment = std::string(engine::render::glsl::kBaseColorSampling) + glsl::kFoliageMotionFragment;
    d.soft = soft::makeKernel<FoliageMotionKernel, AlphaOnlyParams>();
    return d;
}

}  // namespace transparency
