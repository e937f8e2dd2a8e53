// SPDX-License-Identifier: MIT
#include "lightshafts/light_shaft_program.hpp"

#include <cmath>
#include <string>

#include "engine/render/kernel/program_kernel.hpp"
#include "engine/render/shader_interface.hpp"
#include "light_shaft_kernel.hpp"
#include "lightshafts_glsl.hpp"  // generated from glsl/

namespace lightshafts {
namespace {

using namespace engine::render;

void check(const void* params, const DrawCheck& check) {
    const auto& shafts = *static_cast<const LightShaftParams*>(params);
    const Format depthFormat = check.texture(shafts.depth).format;
    if (depthFormat != Format::D32F && depthFormat != Format::R32F)
        check.fail("light-shaft depth is " + std::string(formatName(depthFormat)) + ", not D32F or R32F");
    if (shafts.samples < 1 || shafts.samples > 128)
        check.fail("light-shaft samples " + std::to_string(shafts.samples) + " not in 1..128");
    for (float v : {shafts.sunPixel.x, shafts.sunPixel.y, shafts.farDepth, shafts.intensity, shafts.decay,
                    shafts.density, shafts.color.r, shafts.color.g, shafts.color.b, shafts.glowRadius})
        if (!std::isfinite(v)) check.fail("light-shaft parameters are not finite");
}

}  // namespace

ProgramDesc lightShaftProgram() {
    ProgramDesc d =
        describeProgram<LightShaftParams>("LightShafts", VertexInput::Fullscreen, "lightshafts::LightShaftParams");
    d.gl.fragment = samplerDeclarations(d.gl) + glsl::kLightShaftFragment;
    d.check = check;
    d.soft = soft::makeKernel<LightShaftKernel, LightShaftParams>();
    return d;
}

}  // namespace lightshafts
