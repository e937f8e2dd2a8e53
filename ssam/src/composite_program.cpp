// SPDX-License-Identifier: MIT
#include "ssam/composite_program.hpp"

#include <cmath>
#include <string>

#include "ssam_engine_glsl.hpp"  // generated from engine_glsl/
#include "ssam_glsl.hpp"         // generated from core/glsl/
#include "composite_kernel.hpp"
#include "engine/render/kernel/program_kernel.hpp"

namespace ssam {
namespace {

using namespace engine::render;

std::string fragment() {
    return std::string(engine_glsl::kCompositeHead) + glsl::kCompositeMask + glsl::kCompositeBlur + glsl::kComposite +
           engine_glsl::kCompositeMain;
}

}  // namespace

ProgramDesc compositeProgram() {
    ProgramDesc d = describeProgram<CompositeParams>("Composite", VertexInput::Fullscreen, "ssam::CompositeParams");
    d.gl.fragment = fragment();
    d.check = [](const void* params, const DrawCheck& check) {
        if (!std::isfinite(static_cast<const CompositeParams*>(params)->maskLerp)) check.fail("maskLerp is not finite");
    };
    d.soft = soft::makeKernel<CompositeKernel, CompositeParams>();
    return d;
}

}  // namespace ssam
