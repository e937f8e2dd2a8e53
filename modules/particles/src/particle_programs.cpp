// SPDX-License-Identifier: MIT
#include "particles/particle_programs.hpp"

#include <cmath>
#include <cstddef>
#include <string>

#include "engine/render/kernel/program_kernel.hpp"
#include "engine/render/validation.hpp"
#include "particle_kernels.hpp"

namespace particles {
namespace {

using namespace engine::render;

// Both programs: the closest-sample scene depth for half-resolution layers.
constexpr const char* kParticleDepth = R"(
layout(binding = 0) uniform sampler2D u_sceneDepth;
float saturateOrZero(float v) { return v > 0.0 ? (v < 1.0 ? v : 1.0) : 0.0; }
float closestDepth(ivec2 p, int stride) {
    stride = clamp(stride, 1, 4);
    ivec2 last = textureSize(u_sceneDepth, 0) - 1;
    float best = texelFetch(u_sceneDepth, min(p * stride, last), 0).r;
    for (int sy = 0; sy < stride; ++sy)
        for (int sx = 0; sx < stride; ++sx) {
            float z = texelFetch(u_sceneDepth, min(p * stride + ivec2(sx, sy), last), 0).r;
            if (u_greaterIsCloser ? z > best : z < best) best = z;
        }
    return best;
}
)";

// Particle (particle_kernels.hpp ParticleKernel).
constexpr const char* kParticleFragment = R"(
void main() {
    if (llvmpipeGuard()) discard;
    vec2 q = v_uv * 2.0 - 1.0;
    float shape = saturateOrZero(1.0 - (q.x * q.x + q.y * q.y));
    float fade = 1.0;
    if (u_hasDepth) {
        float z = closestDepth(ivec2(gl_FragCoord.xy), u_depthStride);
        float sceneDistance = u_distanceScale / (z + u_distanceOffset);
        fade = saturateOrZero((sceneDistance - v_normal.x) / u_softness);
    }
    float a = saturateOrZero(v_color.a) * shape * fade;
    float additive = saturateOrZero(v_normal.y);
    vec4 o = vec4(v_color.rgb * a, a * (1.0 - additive));
    for (int c = 0; c < 4; ++c)
        if (isnan(o[c]) || isinf(o[c])) o[c] = 0.0;
    finish(o);
}
)";

// LayerComposite (particle_kernels.hpp LayerCompositeKernel): the layer texel, nearest-depth upsampled.
constexpr const char* kLayerCompositeFragment = R"(
layout(binding = 1) uniform sampler2D u_layer;
float distanceOf(float z) { return u_distanceScale / (z + u_distanceOffset); }
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    int scale = clamp(u_layerScale, 1, 4);
    ivec2 last = textureSize(u_layer, 0) - 1;
    ivec2 l = min(p / scale, last);
    if (scale > 1 && u_hasDepth) {
        float here = distanceOf(texelFetch(u_sceneDepth, p, 0).r);
        ivec2 c0 = clamp((p - 1) / 2, ivec2(0), last), c1 = min(c0 + 1, last);
        ivec2 n = clamp(p / 2, ivec2(0), last);
        vec4 c00 = texelFetch(u_layer, c0, 0);
        bool same = c00 == texelFetch(u_layer, ivec2(c1.x, c0.y), 0) && c00 == texelFetch(u_layer, ivec2(c0.x, c1.y), 0) &&
                    c00 == texelFetch(u_layer, c1, 0);
        if (same) l = c0; else {
        float best = abs(distanceOf(closestDepth(n, scale)) - here);
        l = n;
        for (int j = 0; j < 2; ++j)
            for (int i = 0; i < 2; ++i) {
                ivec2 c = ivec2(i == 0 ? c0.x : c1.x, j == 0 ? c0.y : c1.y);
                float diff = abs(distanceOf(closestDepth(c, scale)) - here);
                if (diff < best) { best = diff; l = c; }
            }
        }
    }
    vec4 c = texelFetch(u_layer, l, 0);
    for (int i = 0; i < 4; ++i)
        if (isnan(c[i]) || isinf(c[i])) c[i] = 0.0;
    c.a = saturateOrZero(c.a);
    finish(c);
}
)";

}  // namespace

ProgramDesc particleProgram() {
    ProgramDesc d = describeProgram<ParticleParams>("Particle", VertexInput::Mesh, "particles::ParticleParams");
    d.gl.fragment = std::string(kParticleDepth) + kParticleFragment;
    d.gl.uniforms = {
        {"u_viewProj", UniformType::Mat4, offsetof(ParticleParams, viewProj)},
        {"u_depthStride", UniformType::Int, offsetof(ParticleParams, depthStride)},
        {"u_distanceScale", UniformType::Float, offsetof(ParticleParams, depthScale)},
        {"u_distanceOffset", UniformType::Float, offsetof(ParticleParams, depthOffset)},
        {"u_softness", UniformType::Float, offsetof(ParticleParams, softness)},
        {"u_greaterIsCloser", UniformType::Bool, offsetof(ParticleParams, greaterIsCloser)},
    };
    d.gl.textures = {{"u_sceneDepth", offsetof(ParticleParams, sceneDepth), 0, TextureRead::Texel, TextureUse::Sampled,
                      true, "u_hasDepth"}};
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
    d.gl.fragment = std::string(kParticleDepth) + kLayerCompositeFragment;
    d.gl.uniforms = {
        {"u_layerScale", UniformType::Int, offsetof(LayerCompositeParams, layerScale)},
        {"u_distanceScale", UniformType::Float, offsetof(LayerCompositeParams, depthScale)},
        {"u_distanceOffset", UniformType::Float, offsetof(LayerCompositeParams, depthOffset)},
        {"u_greaterIsCloser", UniformType::Bool, offsetof(LayerCompositeParams, greaterIsCloser)},
    };
    d.gl.textures = {
        {"u_sceneDepth", offsetof(LayerCompositeParams, sceneDepth), 0, TextureRead::Texel, TextureUse::FullSize, true,
         "u_hasDepth"},
        {"u_layer", offsetof(LayerCompositeParams, layer), 1, TextureRead::Texel, TextureUse::Sampled},
    };
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
