// SPDX-License-Identifier: MIT
// SharpenedCoverageLit's GLSL (transparency/sharpened_coverage.hpp; soft:
// sharpened_coverage_kernel.hpp): the lit surface with glsl/sharpened_coverage_output.glsl as
// its output hook.
#include <cmath>
#include <cstddef>
#include <string>

#include "engine/render/glsl/lit_surface.hpp"
#include "engine/render/kernel/program_kernel.hpp"
#include "sharpened_coverage_kernel.hpp"
#include "transparency_glsl.hpp"  // generated from glsl/

namespace transparency {

using namespace engine::render;

ProgramDesc sharpenedCoverageLitProgram() {
    ProgramDesc d = describeProgram<SharpenedCoverageParams>("SharpenedCoverageLit", VertexInput::Mesh,
                                                             "transparency::SharpenedCoverageParams");
    d.gl.fragment = std::string(engine::render::glsl::kBaseColorSampling) + "#define ALPHA_MASKED 1\n" +
                    glsl::kLodDither + glsl::kSharpenedCoverageOutput + engine::render::glsl::kLitSurface;
    litSurfaceLayout<SharpenedCoverageParams>(d.gl);
    d.gl.uniforms.push_back({"u_reference", UniformType::Float, offsetof(SharpenedCoverageParams, reference)});
    d.gl.uniforms.push_back({"u_lodDither", UniformType::Byte, offsetof(SharpenedCoverageParams, lodDither)});
    d.check = [](const void* params, const DrawCheck& check) {
        const auto& p = *static_cast<const SharpenedCoverageParams*>(params);
        if (!(p.reference >= 0.0f && p.reference <= 1.0f))
            check.fail("reference " + std::to_string(p.reference) + " must be in [0, 1]");
        checkLodDither(p.lodDither, check);
    };
    d.soft = soft::makeKernel<SharpenedCoverageLitKernel, SharpenedCoverageParams>();
    return d;
}

}  // namespace transparency
