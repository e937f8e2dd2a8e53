// SPDX-License-Identifier: MIT
// HashedLit's GLSL (transparency/hashed_alpha.hpp; soft: hashed_kernel.hpp). The threshold
// repeats hashedThreshold()'s operations in its order, `precise` so that no multiply-add is
// fused: with the same uv and derivatives both backends give the same bits.
#include <cstddef>
#include <string>

#include "engine/render/glsl/lit_surface.hpp"
#include "engine/render/kernel/program_kernel.hpp"
#include "hashed_kernel.hpp"
#include "transparency_glsl.hpp"  // generated from glsl/
#include "transparency/hashed_alpha.hpp"

namespace transparency {

using namespace engine::render;

ProgramDesc hashedLitProgram() {
    ProgramDesc d = describeProgram<HashedLitParams>("HashedLit", VertexInput::Mesh, "transparency::HashedLitParams");
    d.gl.fragment = std::string(engine::render::glsl::kBaseColorSampling) + "#define ALPHA_MASKED 1\n" +
                    glsl::kLodDither + glsl::kHashedOutput + engine::render::glsl::kLitSurface;
    litSurfaceLayout<HashedLitParams>(d.gl);
    d.gl.uniforms.push_back({"u_seed", UniformType::Int, offsetof(HashedLitParams, seed)});
    d.gl.uniforms.push_back({"u_hashScale", UniformType::Float, offsetof(HashedLitParams, hashScale)});
    d.gl.uniforms.push_back({"u_anisotropic", UniformType::Bool, offsetof(HashedLitParams, anisotropic)});
    d.gl.uniforms.push_back({"u_outputThreshold", UniformType::Bool, offsetof(HashedLitParams, outputThreshold)});
    d.gl.uniforms.push_back({"u_lodDither", UniformType::Byte, offsetof(HashedLitParams, lodDither)});
    d.check = [](const void* params, const DrawCheck& check) {
        const auto& p = *static_cast<const HashedLitParams*>(params);
        if (!(p.hashScale > 0.0f && p.hashScale < 1e6f))
            check.fail("hashScale " + std::to_string(p.hashScale) + " must be in (0, 1e6)");
        checkLodDither(p.lodDither, check);
    };
    d.soft = soft::makeKernel<HashedLitKernel, HashedLitParams>();
    return d;
}

}  // namespace transparency
