// SPDX-License-Identifier: MIT
#include "gl_shaders.hpp"

#include "engine/render/glsl/lit_surface.hpp"

namespace engine::render::gl {
namespace {

// Vertex stage of every mesh program. Positions are computed with the soft backend's float
// operations in its order (glm: mvp = viewProj * model column by column, then
// (c0*x + c1*y) + (c2*z + c3*w)); `precise` forbids FMA contraction and reassociation, so
// the clip positions, and with them the snapped vertices, agree bit for bit.
constexpr const char* kMeshVertex = R"(#version 450 core
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec2 a_uv;
layout(location = 3) in vec4 a_color;
layout(location = 4) in vec4 a_model0;
layout(location = 5) in vec4 a_model1;
layout(location = 6) in vec4 a_model2;
layout(location = 7) in vec4 a_model3;
layout(location = 8) in vec4 a_tint;

uniform mat4 u_viewProj;

out vec2 v_uv;
out vec3 v_normal;
out vec4 v_color;
flat out int v_instance;  // see kMeshFragmentGuard

vec4 mulColumn(mat4 a, vec4 b) {
    precise vec4 r = a[0] * b.x + a[1] * b.y + a[2] * b.z + a[3] * b.w;
    return r;
}

void main() {
    mat4 model = mat4(a_model0, a_model1, a_model2, a_model3);
    mat4 mvp = mat4(mulColumn(u_viewProj, model[0]), mulColumn(u_viewProj, model[1]),
                    mulColumn(u_viewProj, model[2]), mulColumn(u_viewProj, model[3]));
    precise vec4 xy = mvp[0] * a_position.x + mvp[1] * a_position.y;
    precise vec4 zw = mvp[2] * a_position.z + mvp[3];
    precise vec4 clip = xy + zw;
    gl_Position = clip;
    v_uv = a_uv;
    v_normal = mat3(model) * a_normal;
    v_color = a_color * a_tint;
    v_instance = gl_InstanceID;
}
)";

// Full-screen programs: one triangle covering the viewport, no vertex input.
constexpr const char* kFullscreenVertex = R"(#version 450 core
void main() {
    vec2 p = vec2(float((gl_VertexID & 1) << 2) - 1.0, float((gl_VertexID & 2) << 1) - 1.0);
    gl_Position = vec4(p, 0.0, 1.0);
}
)";

// Shared tail of every program kind: alpha-to-coverage with the soft backend's rule, the
// GS alpha test as a fragment selection, and the colour broadcast to every bound target.
constexpr const char* kFragmentCommon = R"(#version 450 core
layout(location = 0) out vec4 o_color0;
layout(location = 1) out vec4 o_color1;
layout(location = 2) out vec4 o_color2;
layout(location = 3) out vec4 o_color3;

uniform int u_alphaSelect;   // 0 all fragments, 1 those passing the alpha test, 2 those failing it
uniform int u_alphaFunc;     // CompareFunc
uniform float u_alphaRef;
uniform int u_a2cSamples;    // samples of the target as created (0: alpha-to-coverage off)
uniform int u_a2cActual;     // samples GL really allocated (llvmpipe turns 2 into 4)
uniform ivec4 u_scissor;     // x0, y0, x1, y1 of the draw's scissor; x1 = 0: not checked here

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

// Mesh programs read one flat input. llvmpipe (Mesa 22.x) has a fast path for non-indexed
// draws of exactly three triangles whose last one has zero area (lp_setup_analyse_triangles,
// meant for one Windows compositor's rectangles) that draws nothing at all unless the pattern
// is that rectangle; it is skipped when the fragment shader has a flat ("constant") input.
constexpr const char* kMeshFragmentGuard = R"(
flat in int v_instance;
bool llvmpipeGuard() { return v_instance < 0; }  // never true; keeps the input alive
)";

constexpr const char* kFlatFragment = R"(
in vec4 v_color;
uniform vec4 u_color;
void main() {
    if (llvmpipeGuard()) discard;
    finish(u_color * v_color);
}
)";

// [Hathaway 2010] Listing 3.1: alpha only, replicated; no lighting, no colour fetch.
constexpr const char* kAlphaOnlyFragment = R"(
in vec2 v_uv;
in vec4 v_color;
uniform float u_alphaFactor;
uniform bool u_hasTexture;
void main() {
    if (llvmpipeGuard()) discard;
    float a = u_alphaFactor * v_color.a;
    if (u_hasTexture) a *= sampleBase(v_uv).a;
    finish(vec4(a));
}
)";

// Colour resolve: the average of the samples in the linear domain (the fetch decodes sRGB,
// GL_FRAMEBUFFER_SRGB encodes the result), summed in sample order as the soft backend does.
constexpr const char* kResolveColorFragment = R"(#version 450 core
layout(binding = 0) uniform sampler2DMS u_source;
uniform int u_samples;
layout(location = 0) out vec4 o_color;
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    precise vec4 sum = vec4(0.0);
    for (int s = 0; s < u_samples; ++s) sum += texelFetch(u_source, p, s);
    precise vec4 average = sum / float(u_samples);
    o_color = average;
}
)";

// Depth resolve: the sample closest to the observer under the depth function ([Hathaway 2010]
// §3.5.1), never an average.
constexpr const char* kResolveDepthFragment = R"(#version 450 core
layout(binding = 0) uniform sampler2DMS u_source;
uniform int u_samples;
uniform bool u_greater;  // GREATER / GEQUAL: larger is closer (reverse-Z)
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    float best = texelFetch(u_source, p, 0).r;
    for (int s = 1; s < u_samples; ++s) {
        float z = texelFetch(u_source, p, s).r;
        if (u_greater ? z > best : z < best) best = z;
    }
    gl_FragDepth = best;
}
)";

}  // namespace

std::string vertexSource(VertexInput input) {
    return input == VertexInput::Fullscreen ? kFullscreenVertex : kMeshVertex;
}

std::string fragmentSource(VertexInput input, const std::string& body) {
    std::string s = kFragmentCommon;
    if (input == VertexInput::Mesh) s += kMeshFragmentGuard;
    return s + body;
}

std::string standardFragment(ProgramKind kind) {
    switch (kind) {
        case ProgramKind::Flat: return kFlatFragment;
        case ProgramKind::OpaqueLit:
            return std::string(glsl::kBaseColorSampling) + "#define ALPHA_MASKED 0\n" + glsl::kLitSurface;
        case ProgramKind::MaskedLit:
            return std::string(glsl::kBaseColorSampling) + "#define ALPHA_MASKED 1\n" + glsl::kLitSurface;
        case ProgramKind::AlphaOnly: return std::string(glsl::kBaseColorSampling) + kAlphaOnlyFragment;
    }
    return {};
}

std::string withGlslVersion(std::string source, int major, int minor) {
    if (major > 4 || (major == 4 && minor >= 5)) return source;
    const std::string from = "#version 450 core", to = "#version 430 core";  // 4.3/4.4 contexts
    if (source.compare(0, from.size(), from) == 0) source.replace(0, from.size(), to);
    return source;
}

std::string fullscreenVertexSource() { return kFullscreenVertex; }
std::string resolveColorFragmentSource() { return kResolveColorFragment; }
std::string resolveDepthFragmentSource() { return kResolveDepthFragment; }

}  // namespace engine::render::gl
