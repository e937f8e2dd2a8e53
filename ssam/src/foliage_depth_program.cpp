// SPDX-License-Identifier: MIT
#include "foliage_depth_program.hpp"

#include <cmath>
#include <string>

#include "ssam_engine_glsl.hpp"  // generated from engine_glsl/
#include "ssam_glsl.hpp"         // generated from core/glsl/
#include "engine/render/glsl/lit_surface.hpp"
#include "engine/render/kernel/program_kernel.hpp"
#include "foliage_depth_kernel.hpp"

namespace ssam {

using namespace engine::render;

ProgramDesc foliageDepthProgram() {
    ProgramDesc d =
        describeProgram<FoliageDepthParams>("SsamFoliageDepth", VertexInput::Mesh, "ssam::FoliageDepthParams");
    d.gl.fragment = std::string(engine::render::glsl::kBaseColorSampling) + "#define ALPHA_MASKED 1\n" +
                    engine_glsl::kFoliageDepthHead + ssam::glsl::kCompositeMask + ssam::glsl::kFoliageDepthOutput +
                    engine::render::glsl::kLitSurface;
    d.check = [](const void* params, const DrawCheck& check) {
        const auto* p = static_cast<const FoliageDepthParams*>(params);
        if (!std::isfinite(p->maskLerp)) check.fail("maskLerp is not finite");
        if (!std::isfinite(p->threshold)) check.fail("threshold is not finite");
    };
    d.soft = soft::makeKernel<FoliageDepthKernel, FoliageDepthParams>();
    return d;
}

}  // namespace ssam
