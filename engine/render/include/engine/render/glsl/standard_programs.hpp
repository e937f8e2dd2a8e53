// SPDX-License-Identifier: MIT
#pragma once
// GLSL shared by every GLSL-consuming driver (GL, Vulkan): the fragment tail every program
// ends in (finish()), the mesh programs' guard, and the standard programs' bodies (what
// kernel/programs.hpp computes, line for line). Bodies declare no uniforms and no
// interpolants: the driver declares them from the program's layout (shader_interface.hpp).
#include <string>

#include "engine/render/glsl/lit_surface.hpp"
#include "engine/render/program.hpp"

namespace engine::render::glsl {

// The tail's inputs, which the driver declares (driver_stages.cpp; GL: loose uniforms, Vulkan:
// push constants):
//   int u_alphaSelect   0 all fragments, 1 those passing the alpha test, 2 those failing it
//   int u_alphaFunc     CompareFunc
//   float u_alphaRef
//   int u_a2cSamples    samples of the target as created (0: alpha-to-coverage off)
//   int u_a2cActual     samples the API really allocated (llvmpipe GL turns 2 into 4)
//   ivec4 u_scissor     x0, y0, x1, y1 of the draw's scissor; x1 = 0: not checked here
// Alpha-to-coverage with the soft backend's rule, the GS alpha test as a fragment selection,
// and the colour broadcast to every bound target.
inline constexpr const char* kFinish = R"(
float clamp01(float v) { return v > 0.0 ? (v < 1.0 ? v : 1.0) : 0.0; }

bool alphaPasses(float a) {
    switch (u_alphaFunc) {
        case 0: return false;
        case 1: return a < u_alphaRef;
        case 2: return a == u_alphaRef;
        case 3: return a <= u_alphaRef;
        case 4: return a > u_alphaRef;
        case 5: return a != u_alphaRef;
        case 6: return a >= u_alphaRef;
        default: return true;
    }
}

void finish(vec4 color) {
    // Multisampled targets: the scissor again, per pixel. llvmpipe (Mesa 22.x) tests the
    // scissor rectangle at sample positions half a pixel off and lets the column left of it
    // and the row above it through; glScissor still bounds the work.
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    if (u_scissor.z > 0 && (any(lessThan(pixel, u_scissor.xy)) || any(greaterThanEqual(pixel, u_scissor.zw)))) discard;
    int mask = -1;
    if (u_a2cSamples > 1) {
        // round(alpha * samples) samples, the first ones (tile_rasterizer.cpp); a 2x target that
        // GL made 4x covers the same fraction of its samples.
        precise float scaled = clamp01(color.a) * float(u_a2cSamples) + 0.5;
        int covered = int(scaled) * u_a2cActual / u_a2cSamples;
        mask = (1 << covered) - 1;
    }
    gl_SampleMask[0] = mask;
    if (u_alphaSelect != 0 && alphaPasses(color.a) != (u_alphaSelect == 1)) discard;
    o_color0 = color;
    o_color1 = color;
    o_color2 = color;
    o_color3 = color;
}
)";

// Mesh programs read one flat input (v_instance). llvmpipe (Mesa 22.x) has a fast path for
// non-indexed draws of exactly three triangles whose last one has zero area
// (lp_setup_analyse_triangles, meant for one Windows compositor's rectangles) that draws
// nothing at all unless the pattern is that rectangle; it is skipped when the fragment shader
// has a flat ("constant") input.
inline constexpr const char* kMeshFragmentGuard = R"(
bool llvmpipeGuard() { return v_instance < 0; }  // never true; keeps the input alive
)";

inline constexpr const char* kFlatFragment = R"(
void main() {
    if (llvmpipeGuard()) discard;
    finish(u_color * v_color);
}
)";

// [Hathaway 2010] Listing 3.1: alpha only, replicated; no lighting, no colour fetch.
inline constexpr const char* kAlphaOnlyFragment = R"(
void main() {
    if (llvmpipeGuard()) discard;
    float a = u_alphaFactor * v_color.a;
    if (u_hasTexture) a *= sampleBase(v_uv).a;
    finish(vec4(a));
}
)";

// The fragment body of a standard program (standard_programs.hpp).
inline std::string standardFragmentBody(ProgramKind kind) {
    switch (kind) {
        case ProgramKind::Flat: return kFlatFragment;
        case ProgramKind::OpaqueLit: return std::string(kBaseColorSampling) + "#define ALPHA_MASKED 0\n" + kLitSurface;
        case ProgramKind::MaskedLit: return std::string(kBaseColorSampling) + "#define ALPHA_MASKED 1\n" + kLitSurface;
        case ProgramKind::AlphaOnly: return std::string(kBaseColorSampling) + kAlphaOnlyFragment;
    }
    return {};
}

}  // namespace engine::render::glsl
