// SPDX-License-Identifier: MIT
#include "transparency/programs.hpp"

#include <cstddef>
#include <string>

#include "engine/render/glsl/lit_surface.hpp"
#include "engine/render/kernel/program_kernel.hpp"
#include "program_kernels.hpp"

namespace transparency {
namespace {

using namespace engine::render;

// WboitAccumulate: the lit surface's output hook wboitWeighted() (soft: program_kernels.hpp
// wboitWeight, the same operations in the same order). McGuire & Bavoil 2013, eq. (7), with
// the view depth |z| = clip w = 1 / gl_FragCoord.w.
constexpr const char* kWboitWeight = R"(
#define SURFACE_OUTPUT wboitWeighted
vec4 wboitWeighted(vec4 c) {
    precise float z = abs((1.0 / gl_FragCoord.w) * u_depthScale);
    precise float near = z / 5.0, far = z / 200.0;
    precise float far2 = far * far;
    precise float g = 10.0 / (1e-5 + near * near + far2 * far2 * far2);
    precise float w = c.a * (g > 1e-2 ? (g < 3e3 ? g : 3e3) : 1e-2);
    precise float aw = c.a * w;
    return vec4(c.rgb * aw, aw);
}
)";

// The WBOIT composite (McGuire & Bavoil 2013): average colour and revealage; the blend
// (INV_SRC_ALPHA / SRC_ALPHA) puts it over the opaque colour.
constexpr const char* kWboitResolveFragment = R"(
layout(binding = 0) uniform sampler2D u_accumulation;
layout(binding = 1) uniform sampler2D u_revealage;
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec4 sum = texelFetch(u_accumulation, p, 0);
    float reveal = clamp01(texelFetch(u_revealage, p, 0).r);
    float weight = sum.a > 1e-5 ? sum.a : 1e-5;
    vec3 average = sum.rgb / weight;
    for (int c = 0; c < 3; ++c)
        if (isnan(average[c]) || isinf(average[c])) average[c] = 0.0;
    finish(vec4(average, reveal));
}
)";

// SSAM+'s coverage from the MAX and ADD masks (soft: program_kernels.hpp layerCoverage).
constexpr const char* kLayerCoverage = R"(
layout(binding = 0) uniform sampler2D u_foliage;
layout(binding = 1) uniform sampler2D u_mask;
layout(binding = 2) uniform sampler2D u_maskAdd;
float layerCoverage(ivec2 p) {
    vec4 m = texelFetch(u_mask, p, 0);
    float addMask = u_hasMaskAdd ? texelFetch(u_maskAdd, p, 0).r : m.a;
    float coverage = 0.0;
    if (u_coverageModel == 1) coverage = 1.0 - exp(-addMask);
    else if (m.r >= 1.0) coverage = 1.0;
    else if (m.r > 0.0) coverage = 1.0 - pow(1.0 - m.r, addMask / m.r);
    return clamp01(coverage);
}
)";

// SSAM+'s composite (soft: program_kernels.hpp CoverageCompositeKernel).
constexpr const char* kCoverageCompositeMain = R"(
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec3 color = texelFetch(u_foliage, p, 0).rgb;
    for (int c = 0; c < 3; ++c)
        if (isnan(color[c]) || isinf(color[c])) color[c] = 0.0;
    finish(vec4(color, layerCoverage(p)));
}
)";

// SSAM+'s blurred composite (soft: program_kernels.hpp CoverageBlurCompositeKernel, summed in
// the same order).
constexpr const char* kCoverageBlurCompositeMain = R"(
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    ivec2 size = textureSize(u_foliage, 0);
    vec3 sum = vec3(0.0);
    float weights = 0.0;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            ivec2 q = p + ivec2(dx, dy);
            if (q.x < 0 || q.y < 0 || q.x >= size.x || q.y >= size.y) continue;
            vec4 c = texelFetch(u_foliage, q, 0);
            if (!(c.a > 0.0)) continue;
            float weight = float((2 - dx * dx) * (2 - dy * dy));
            sum += weight * c.rgb;
            weights += weight;
        }
    vec3 color = weights > 0.0 ? sum / weights : texelFetch(u_foliage, p, 0).rgb;
    for (int c = 0; c < 3; ++c)
        if (isnan(color[c]) || isinf(color[c])) color[c] = 0.0;
    finish(vec4(color, layerCoverage(p)));
}
)";

// The exact reference's composite (soft: program_kernels.hpp TransmittanceCompositeKernel).
constexpr const char* kTransmittanceCompositeFragment = R"(
layout(binding = 0) uniform sampler2D u_color;
layout(binding = 1) uniform sampler2D u_transmittance;
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec3 color = texelFetch(u_color, p, 0).rgb;
    for (int c = 0; c < 3; ++c)
        if (isnan(color[c]) || isinf(color[c])) color[c] = 0.0;
    finish(vec4(color, clamp01(texelFetch(u_transmittance, p, 0).r)));
}
)";

// Both SSAM+ composites: the same params, textures and checks; `blur` picks the colour.
ProgramDesc coverageComposite(bool blur) {
    ProgramDesc d =
        describeProgram<CoverageCompositeParams>(blur ? "CoverageBlurComposite" : "CoverageComposite",
                                                 VertexInput::Fullscreen, "transparency::CoverageCompositeParams");
    d.gl.fragment = std::string(kLayerCoverage) + (blur ? kCoverageBlurCompositeMain : kCoverageCompositeMain);
    d.gl.uniforms = {{"u_coverageModel", UniformType::Byte, offsetof(CoverageCompositeParams, model)}};
    d.gl.textures = {
        {"u_foliage", offsetof(CoverageCompositeParams, foliage), 0, TextureRead::Texel, TextureUse::FullSize},
        {"u_mask", offsetof(CoverageCompositeParams, mask), 1, TextureRead::Texel, TextureUse::FullSize},
        {"u_maskAdd", offsetof(CoverageCompositeParams, maskAdd), 2, TextureRead::Texel, TextureUse::FullSize, true,
         "u_hasMaskAdd"},
    };
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
    d.gl.fragment =
        std::string(glsl::kBaseColorSampling) + "#define ALPHA_MASKED 1\n" + kWboitWeight + glsl::kLitSurface;
    litSurfaceLayout<WboitAccumulateParams>(d.gl);  // the surface it weights
    d.gl.uniforms.push_back({"u_depthScale", UniformType::Float, offsetof(WboitAccumulateParams, depthScale)});
    d.soft = soft::makeKernel<WboitAccumulateKernel, WboitAccumulateParams>();
    return d;
}

ProgramDesc wboitResolveProgram() {
    ProgramDesc d = describeProgram<WboitResolveParams>("WboitResolve", VertexInput::Fullscreen,
                                                        "transparency::WboitResolveParams");
    d.gl.fragment = kWboitResolveFragment;
    d.gl.textures = {
        {"u_accumulation", offsetof(WboitResolveParams, accumulation), 0, TextureRead::Texel, TextureUse::FullSize},
        {"u_revealage", offsetof(WboitResolveParams, revealage), 1, TextureRead::Texel, TextureUse::FullSize},
    };
    d.soft = soft::makeKernel<WboitResolveKernel, WboitResolveParams>();
    return d;
}

ProgramDesc coverageCompositeProgram() { return coverageComposite(false); }
ProgramDesc coverageBlurCompositeProgram() { return coverageComposite(true); }

ProgramDesc transmittanceCompositeProgram() {
    ProgramDesc d = describeProgram<TransmittanceCompositeParams>("TransmittanceComposite", VertexInput::Fullscreen,
                                                                  "transparency::TransmittanceCompositeParams");
    d.gl.fragment = kTransmittanceCompositeFragment;
    d.gl.textures = {
        {"u_color", offsetof(TransmittanceCompositeParams, color), 0, TextureRead::Texel, TextureUse::FullSize},
        {"u_transmittance", offsetof(TransmittanceCompositeParams, transmittance), 1, TextureRead::Texel,
         TextureUse::FullSize},
    };
    d.soft = soft::makeKernel<TransmittanceCompositeKernel, TransmittanceCompositeParams>();
    return d;
}

}  // namespace transparency
