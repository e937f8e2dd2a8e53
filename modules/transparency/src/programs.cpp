// SPDX-License-Identifier: MIT
#include "transparency/programs.hpp"

#include <string>

#include "engine/render/glsl/lit_surface.hpp"
#include "engine/render/kernel/program_kernel.hpp"
#include "engine/render/shader_interface.hpp"
#include "program_kernels.hpp"
#include "ssam_glsl.hpp"          // generated from ssam/src/core/glsl/
#include "transparency_glsl.hpp"  // generated from glsl/

namespace transparency {
namespace {

using namespace engine::render;

// A full-screen program whose fragment shader is its samplers' declarations and `fragment`.
template <typename Params, typename Kernel>
ProgramDesc fullscreenProgram(const char* name, const char* paramsName, const char* fragment) {
    ProgramDesc d = describeProgram<Params>(name, VertexInput::Fullscreen, paramsName);
    d.gl.fragment = samplerDeclarations(d.gl) + fragment;
    d.soft = soft::makeKernel<Kernel, Params>();
    return d;
}

// Both SSAM+ composites: the same params, textures and checks; `blur` picks the colour.
ProgramDesc coverageComposite(bool blur) {
    ProgramDesc d =
        describeProgram<CoverageCompositeParams>(blur ? "CoverageBlurComposite" : "CoverageComposite",
                                                 VertexInput::Fullscreen, "transparency::CoverageCompositeParams");
    d.gl.fragment = samplerDeclarations(d.gl) + glsl::kLayerCoverage + glsl::kFrontLayers +
                    (blur ? std::string(ssam::glsl::kCompositeBlur) + glsl::kCoverageBlurCompositeMain
                          : std::string(glsl::kCoverageCompositeMain));
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
    d.soft = soft::makeKernel<WboitAccumulateKernel, WboitAccumulateParams>();
    return d;
}

ProgramDesc wboitResolveProgram() {
    return fullscreenProgram<WboitResolveParams, WboitResolveKernel>("WboitResolve", "transparency::WboitResolveParams",
                                                                     glsl::kWboitResolveFragment);
}

ProgramDesc coverageCompositeProgram() { return coverageComposite(false); }
ProgramDesc coverageBlurCompositeProgram() { return coverageComposite(true); }

ProgramDesc transmittanceCompositeProgram() {
    return fullscreenProgram<TransmittanceCompositeParams, TransmittanceCompositeKernel>(
        "TransmittanceComposite", "transparency::TransmittanceCompositeParams", glsl::kTransmittanceCompositeFragment);
}

}  // namespace transparency
