// SPDX-License-Identifier: MIT
#pragma once
// GLSL of the engine's lit, textured surface, shared by its standard programs on the GL
// backend and by modules whose programs shade a surface the same way and then post-process
// the colour (program_desc.hpp: a module's GlslProgram::fragment may start with these).
namespace engine::render::glsl {

inline constexpr const char* kBaseColorSampling = R"(
// Base colour sampling. Nearest and bilinear are the sampler's (GL_NEAREST / GL_LINEAR: the
// base level only). Trilinear computes its LOD here, as the soft backend does: rho is the
// longer analytic UV derivative in texels, lambda = log2 rho, and the two nearest levels are
// lerped. GL's own LOD takes finite differences of uv and leaves precision to the
// implementation (llvmpipe quantizes the fraction); here the derivatives are analytic:
// uv/w and 1/w (gl_FragCoord.w) are linear in screen space, so their differences are exact and
// d(uv)/dx = (d(uv/w)/dx - uv * d(1/w)/dx) * w (soft: tile_rasterizer.cpp interpolate()).
layout(binding = 0) uniform sampler2D u_baseColor;
vec4 sampleBase(vec2 uv) {
    float inverseW = gl_FragCoord.w;
    vec2 uvOverW = uv * inverseW;
    // Linear functions: fine and coarse differences agree, so plain dFdx (GLSL 4.30) will do.
    vec2 dqdx = dFdx(uvOverW), dqdy = dFdy(uvOverW);
    float dwdx = dFdx(inverseW), dwdy = dFdy(inverseW);
    if (u_filter != 2) return texture(u_baseColor, uv);
    float w = 1.0 / inverseW;
    vec2 size = vec2(textureSize(u_baseColor, 0));
    vec2 dx = (dqdx - uv * dwdx) * w * size;
    vec2 dy = (dqdy - uv * dwdy) * w * size;
    float rho = max(length(dx), length(dy));
    float lambda = log2(rho);
    int last = textureQueryLevels(u_baseColor) - 1;
    if (!(lambda > 0.0) || last == 0) return textureLod(u_baseColor, uv, 0.0);
    if (lambda >= float(last)) return textureLod(u_baseColor, uv, float(last));
    int lo = int(lambda);
    return mix(textureLod(u_baseColor, uv, float(lo)), textureLod(u_baseColor, uv, float(lo + 1)), lambda - float(lo));
}
)";

// The lit surface (OpaqueLit, MaskedLit; soft: kernel/programs.hpp SurfaceProgram). Defines
// main(). Before it: kBaseColorSampling and `#define ALPHA_MASKED 0` (opaque: alpha 1) or
// `1` (double-sided, alpha kept); a program that post-processes the masked colour defines
// SURFACE_OUTPUT(c) as a function of it (transparency's WBOIT accumulation does).
inline constexpr const char* kLitSurface = R"(
// u_towardLight is normalised on the CPU, as glm::normalize does in the soft backend
// (UniformType::Direction).

vec4 toStraight(vec4 t) {
    if (!u_premultiplied || !(t.a > 0.0)) return t;
    return vec4(t.rgb / t.a, t.a);
}

float lambert(vec3 n) {
    float len = length(n);
    if (!(len > 0.0)) return 0.0;
    return max(dot(n / len, u_towardLight), 0.0);
}

void main() {
    if (llvmpipeGuard()) discard;
    vec4 base = u_color * v_color;
    if (u_hasTexture) base *= toStraight(sampleBase(v_uv));
    vec3 n = v_normal;
#if ALPHA_MASKED
    if (!gl_FrontFacing) n = -n;  // double-sided: back faces lit with the flipped normal
#endif
    vec3 lit = base.rgb * (u_ambient + u_lightColor * lambert(n));
#if ALPHA_MASKED
#ifdef SURFACE_OUTPUT
    finish(SURFACE_OUTPUT(vec4(lit, base.a)));
#else
    finish(vec4(lit, base.a));
#endif
#else
    finish(vec4(lit, 1.0));
#endif
}
)";

}  // namespace engine::render::glsl
