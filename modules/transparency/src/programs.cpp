// SPDX-License-Identifier: MIT
#include "transparency/programs.hpp"

#include <cstddef>
#include <string>

#include "engine/render/glsl/lit_surface.hpp"
#include "engine/render/kernel/program_kernel.hpp"
#include "engine/render/shader_interface.hpp"
#include "program_kernels.hpp"
#include "transparency_glsl.hpp"  // generated from glsl/

namespace transparency {
namespace {

using namespace engine::render;

// Both SSAM+ composites: the same params, textures and checks; `blur` picks the colour.
ProgramDesc coverageComposite(bool blur) {
    ProgramDesc d =
        describeProgram<CoverageCompositeParams>(blur ? "CoverageBlurComposite" : "CoverageComposite",
                                                 VertexInput::Fullscreen, "transparency::CoverageCompositeParams");
    d.gl.fragment = samplerDeclarations(d.gl) + glsl::kLayerCoverage +
                    (blur ? glsl::kCoverageBlurCompositeMain : glsl::kCoverageCompositeMain);
    d.check = [](const void* params, const DrawCheck& check) {
        const CoverageModel model = static_cast<const CoverageCompositeParams*>(params)->model;
        if (model != CoverageModel::EqualLayers && model != CoverageModel::Exponential)
            check.fail("unknown coverage model " + std::to_string(int(model)));
    };
    d.soft = blur ? soft::makeKernel<CoverageBlurCompositeKernel, CoverageCompositeParams>()
                  : soft::makeKernel<CoverageCompositeKernel, CoverageCompositeParams>();
    return d;
}

}  // namespace

ProgramDesc wboitAccumulateProgram() {
    ProgramDesc d = describeProgram<WboitAccumulateParams>("WboitAccumulate", VertexInput::Mesh,
                                                           "transparency::WboitAccumulateParams");
    d.gl.fragment = std::string(engine::render::glsl::kBaseColorSampling) + "#define ALPHA_MASKED 1\n" +
                    glsl::kWboitWeight + engine::render::glsl::kLitSurface;
    litSurfaceLayout<WboitAccumulateParams>(d.gl);  // the surface it weights
    d.gl.uniforms.push_back({"u_depthScale", UniformType::Float, offsetof(WboitAccumulateParams, depthScale)});
    d.soft = soft::makeKernel<WboitAccumulateKernel, WboitAccumulateParams>();
    return d;
}

ProgramDesc wboitResolveProgram() {
    ProgramDesc d = describeProgram<WboitResolveParams>("WboitResolve", VertexInput::Fullscreen,
                                                        "transparency::WboitResolveParams");
    d.gl.fragment = samplerDeclarations(d.gl) + glsl::kWboitResolveFragment;
    d.soft = soft::makeKernel<WboitResolveKernel, WboitResolveParams>();
    return d;
}

ProgramDesc coverageCompositeProgram() { return coverageComposite(false); }
ProgramDesc coverageBlurCompositeProgram() { return coverageComposite(true); }

ProgramDesc transmittanceCompositeProgram() {
    ProgramDesc d = describeProgram<TransmittanceCompositeParams>("TransmittanceComposite", VertexInput::Fullscreen,
                                                                  "transparency::TransmittanceCompositeParams");
    d.gl.fragment = samplerDeclarations(d.gl) + glsl::kTransmittanceCompositeFragment;
    d.soft = soft::makeKernel<TransmittanceCompositeKernel, TransmittanceCompositeParams>();
    return d;
}

}  // namespace transparency
