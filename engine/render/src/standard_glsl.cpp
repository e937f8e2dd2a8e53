// SPDX-License-Identifier: MIT
// The engine's own GLSL (glsl/standard_programs.hpp, glsl/lit_surface.hpp), from the .glsl files
// in engine/render/glsl/ that the build embeds (engine/cmake/glsl.cmake).
#include "engine/render/glsl/standard_programs.hpp"

#include "engine_render_glsl.hpp"  // generated from glsl/

namespace engine::render::glsl {

const char* const kFinish = embedded::kFinish;
const char* const kBaseColorSampling = embedded::kBaseColorSampling;
const char* const kLitSurface = embedded::kLitSurface;

std::string standardFragmentBody(ProgramKind kind) {
    switch (kind) {
        case ProgramKind::Flat: return embedded::kFlatFragment;
        case ProgramKind::OpaqueLit:
            return std::string(embedded::kBaseColorSampling) + "#define ALPHA_MASKED 0\n" + embedded::kLitSurface;
        case ProgramKind::MaskedLit:
            return std::string(embedded::kBaseColorSampling) + "#define ALPHA_MASKED 1\n" + embedded::kLitSurface;
        case ProgramKind::AlphaOnly: return std::string(embedded::kBaseColorSampling) + embedded::kAlphaOnlyFragment;
    }
    return {};
}

}  // namespace engine::render::glsl
