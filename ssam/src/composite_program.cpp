// SPDX-License-Identifier: MIT
#include "ssam/composite_program.hpp"

#include <cmath>
#include <cstddef>
#include <string>

#include "ssam_engine_glsl.hpp"  // generated from engine_glsl/
#include "ssam_glsl.hpp"         // generated from core/glsl/
#include "composite_kernel.hpp"
#include "engine/render/kernel/program_kernel.hpp"

namespace ssam {
namespace {

using namespace engine::render;

std::string fragment() {
    return std::string(engine_glsl::kCompositeHead) + glsl::kCompositeMask + glsl::kComposite +
           engine_glsl::kCompositeMain;
}

}  // namespace

ProgramDesc compositeProgram() {
    ProgramDesc d = describeProgram<CompositeParams>("Composite", VertexInput::Fullscreen, "ssam::CompositeParams");
    d.gl.fragment = fragment();
    d.gl.uniforms = {{"u_maskLerp", UniformType::Float, offsetof(CompositeParams, maskLerp)},
                     {"u_squareMask", UniformType::Bool, offsetof(CompositeParams, squareMask)}};
    // Read at every target pixel: at least the target's size.
    d.gl.textures = {
        {"u_foliage", offsetof(CompositeParams, foliage), 0, TextureRead::Texel, TextureUse::FullSize},
        {"u_mask", offsetof(CompositeParams, mask), 1, TextureRead::Texel, TextureUse::FullSize},
        {"u_maskAdd", offsetof(CompositeParams, maskAdd), 2, TextureRead::Texel, TextureUse::FullSize, true,
         "u_hasMaskAdd"},
    };
    d.check = [](const void* params, const DrawCheck& check) {
        if (!std::isfinite(static_cast<const CompositeParams*>(params)->maskLerp)) check.fail("maskLerp is not finite");
    };
    d.soft = soft::makeKernel<CompositeKernel, CompositeParams>();
    return d;
}

}  // namespace ssam
