// SPDX-License-Identifier: MIT
#include "particles/particle_programs.hpp"

#include <cmath>
#include <string>

#include "engine/render/kernel/program_kernel.hpp"
#include "engine/render/shader_interface.hpp"
#include "engine/render/validation.hpp"
#include "particle_kernels.hpp"
#include "particles_glsl.hpp"  // generated from glsl/

namespace particles {
namespace {

using namespace engine::render;

// The samplers the parameter block declares, then the bodies (glsl/*.glsl).
std::string fragment(const GlslProgram& gl, const char* body) {
    return samplerDeclarations(gl) + glsl::kParticleDepth + body;
}

}  // namespace

ProgramDesc particleProgram() {
    ProgramDesc d = describeProgram<ParticleParams>("Particle", VertexInput::Mesh, "particles::ParticleParams");
    d.gl.fragment = fragment(d.gl, glsl::kParticleFragment);
    d.check = [](const void* params, const DrawCheck& check) {
        const auto& p = *static_cast<const ParticleParams*>(params);
        if (p.depthStride != 1 && p.depthStride != 2)
            check.fail("depthStride " + std::to_string(p.depthStride) + " is not 1 or 2");
        if (!(p.softness > 0.0f) || !std::isfinite(p.softness)) check.fail("softness must be finite and > 0");
        if (!std::isfinite(p.depthScale) || !std::isfinite(p.depthOffset))
            check.fail("depth-to-distance factors are not finite");
    };
    d.soft = soft::makeKernel<ParticleKernel, ParticleParams>();
    return d;
}

ProgramDesc layerCompositeProgram() {
    ProgramDesc d = describeProgram<LayerCompositeParams>("LayerComposite", VertexInput::Fullscreen,
                                                          "particles::LayerCompositeParams");
    d.gl.fragment = fragment(d.gl, glsl::kLayerCompositeFragment);
    d.check = [](const void* params, const DrawCheck& check) {
        // A layer of 1/layerScale the target's size (rounded up), upsampled by the program.
        const auto& l = *static_cast<const LayerCompositeParams*>(params);
        if (l.layerScale != 1 && l.layerScale != 2)
            check.fail("layerScale " + std::to_string(l.layerScale) + " is not 1 or 2");
        const TextureDesc& t = check.texture(l.layer);
        const int s = l.layerScale;
        if (t.width < (check.targetWidth() + s - 1) / s || t.height < (check.targetHeight() + s - 1) / s)
            check.fail("layer " + quotedName(t.name) + " is smaller than the target / " + std::to_string(s));
        if (!std::isfinite(l.depthScale) || !std::isfinite(l.depthOffset))
            check.fail("depth-to-distance factors are not finite");
    };
    d.soft = soft::makeKernel<LayerCompositeKernel, LayerCompositeParams>();
    return d;
}

}  // namespace particles
