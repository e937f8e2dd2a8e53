// SPDX-License-Identifier: MIT
#include "lightshafts/light_shaft_program.hpp"

#include <cmath>
#include <cstddef>
#include <string>

#include "engine/render/kernel/program_kernel.hpp"
#include "light_shaft_kernel.hpp"

namespace lightshafts {
namespace {

using namespace engine::render;

// The march of LightShaftKernel (light_shaft_kernel.hpp), sample point for sample point;
// `precise` keeps the compiler from contracting the additions into FMAs, so GL marches
// through the same texels as the soft backend.
constexpr const char* kFragment = R"(
layout(binding = 0) uniform sampler2D u_shaftDepth;
float sunGlow(vec2 q) {
    if (!(u_glowRadius > 0.0)) return 1.0;
    float t = max(0.0, 1.0 - length(q - u_sunPixel) / u_glowRadius);
    return t * t;
}
void main() {
    ivec2 size = textureSize(u_shaftDepth, 0);
    int samples = clamp(u_samples, 1, 128);
    precise vec2 p = floor(gl_FragCoord.xy) + 0.5;
    precise vec2 step = (u_sunPixel - p) * (u_density / float(samples));
    float sum = 0.0, weight = 1.0;
    for (int i = 0; i < samples; ++i) {
        precise vec2 q = p + step * float(i);
        if (!(q.x >= 0.0 && q.y >= 0.0 && q.x < float(size.x) && q.y < float(size.y))) break;
        float z = texelFetch(u_shaftDepth, ivec2(q), 0).r;
        bool sky = u_shaftGreater ? !(z > u_farDepth) : !(z < u_farDepth);
        if (sky) sum += weight * sunGlow(q);
        weight *= u_decay;
    }
    vec3 c = u_shaftColor * (u_intensity * sum / float(samples));
    for (int i = 0; i < 3; ++i)
        if (isnan(c[i]) || isinf(c[i])) c[i] = 0.0;
    finish(vec4(c, 0.0));
}
)";

void check(const void* params, const DrawCheck& check) {
    const auto& shafts = *static_cast<const LightShaftParams*>(params);
    const Format depthFormat = check.texture(shafts.depth).format;
    if (depthFormat != Format::D32F && depthFormat != Format::R32F)
        check.fail("light-shaft depth is " + std::string(formatName(depthFormat)) + ", not D32F or R32F");
    if (shafts.samples < 1 || shafts.samples > 128)
        check.fail("light-shaft samples " + std::to_string(shafts.samples) + " not in 1..128");
    for (float v : {shafts.sunPixel.x, shafts.sunPixel.y, shafts.farDepth, shafts.intensity, shafts.decay,
                    shafts.density, shafts.color.r, shafts.color.g, shafts.color.b, shafts.glowRadius})
        if (!std::isfinite(v)) check.fail("light-shaft parameters are not finite");
}

}  // namespace

ProgramDesc lightShaftProgram() {
    ProgramDesc d =
        describeProgram<LightShaftParams>("LightShafts", VertexInput::Fullscreen, "lightshafts::LightShaftParams");
    d.gl.fragment = kFragment;
    d.gl.uniforms = {
        {"u_sunPixel", UniformType::Vec2, offsetof(LightShaftParams, sunPixel)},
        {"u_farDepth", UniformType::Float, offsetof(LightShaftParams, farDepth)},
        {"u_shaftGreater", UniformType::Bool, offsetof(LightShaftParams, greaterIsCloser)},
        {"u_shaftColor", UniformType::Vec3, offsetof(LightShaftParams, color)},
        {"u_intensity", UniformType::Float, offsetof(LightShaftParams, intensity)},
        {"u_decay", UniformType::Float, offsetof(LightShaftParams, decay)},
        {"u_density", UniformType::Float, offsetof(LightShaftParams, density)},
        {"u_samples", UniformType::Int, offsetof(LightShaftParams, samples)},
        {"u_glowRadius", UniformType::Float, offsetof(LightShaftParams, glowRadius)},
    };
    // Read at every target pixel: at least the target's size.
    d.gl.textures = {{"u_shaftDepth", offsetof(LightShaftParams, depth), 0, TextureRead::Texel, TextureUse::FullSize}};
    d.check = check;
    d.soft = soft::makeKernel<LightShaftKernel, LightShaftParams>();
    return d;
}

}  // namespace lightshafts
