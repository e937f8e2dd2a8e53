// SPDX-License-Identifier: MIT
// DitheredMaskedLit's GLSL (transparency/lod_dither.hpp; soft: lod_dither_kernel.hpp): the lit
// surface with glsl/lod_dither.glsl as its output hook.
#include <string>

#include "engine/render/glsl/lit_surface.hpp"
#include "engine/render/kernel/program_kernel.hpp"
#include "lod_dither_kernel.hpp"
#include "transparency_glsl.hpp"  // generated from glsl/

namespace transparency {

using namespace engine::render;

void checkLodDither(LodDither dither, const DrawCheck& check) {
    if (dither != LodDither::Off && dither != LodDither::KeepBelow && dither != LodDither::KeepAbove)
        check.fail("lodDither " + std::to_string(int(dither)) + " is not a LodDither");
}

ProgramDesc ditheredMaskedLitProgram() {
    ProgramDesc d = describeProgram<DitheredSurfaceParams>("DitheredMaskedLit", VertexInput::Mesh,
                                                           "transparency::DitheredSurfaceParams");
    d.gl.fragment = std::string(engine::render::glsl::kBaseColorSampling) + "#define ALPHA_MASKED 1\n" +
                    glsl::kLodDither + "#define SURFACE_OUTPUT(c) lodDitherOutput(c, v_color.a)\n" +
                    engine::render::glsl::kLitSurface;
    d.check = [](const void* params, const DrawCheck& check) {
        checkLodDither(static_cast<const DitheredSurfaceParams*>(params)->lodDither, check);
    };
    d.soft = soft::makeKernel<DitheredMaskedLitKernel, DitheredSurfaceParams>();
    return d;
}

}  // namespace transparency
