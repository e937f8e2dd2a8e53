// SPDX-License-Identifier: MIT
#pragma once
// The GLSL of SSAM's composite (composite_program.hpp), one source for the engine's GL
// backend and for ssam::gl: each declares the samplers and uniforms the way its GLSL version
// allows, defines PRECISE (`precise` from GLSL 4.00, empty before) and appends this.
namespace ssam::glsl {

// The composite's mask (§3.5.4, Listing 3.2; §3.6.2). Needs u_mask, u_maskAdd (sampler2D),
// u_hasMaskAdd, u_squareMask (bool), u_maskLerp (float). Defines float ssamCompositeMask(ivec2).
inline constexpr const char* kCompositeMask = R"(
float ssamCompositeMask(ivec2 p) {
    vec4 m = texelFetch(u_mask, p, 0);
    float addMask = u_hasMaskAdd ? texelFetch(u_maskAdd, p, 0).r : m.a;
    PRECISE float blend = m.r + (addMask - m.r) * u_maskLerp;
    blend = blend > 0.0 ? (blend < 1.0 ? blend : 1.0) : 0.0;  // NaN -> 0
    if (u_squareMask) blend *= blend;  // the squared alpha trick ([Hathaway 2010] §3.6.2)
    return blend;
}
)";

// After kCompositeMask; needs u_foliage (sampler2D) too. Defines vec4 ssamComposite(ivec2 pixel).
inline constexpr const char* kComposite = R"(
vec4 ssamComposite(ivec2 p) {
    // A non-finite foliage colour (HDR lighting, hostile data) composites as black.
    vec3 color = texelFetch(u_foliage, p, 0).rgb;
    for (int c = 0; c < 3; ++c)
        if (isnan(color[c]) || isinf(color[c])) color[c] = 0.0;
    return vec4(color, ssamCompositeMask(p));
}
)";

// Settings::depthMaskThreshold (ssam::gl and ssam::vk): the composite's mask (the function above)
// against the threshold; below it the opaque depth saved before the colour pass goes back.
// Needs kCompositeMask's and kComposite's names and u_opaqueDepth (sampler2D), u_threshold (float).
inline constexpr const char* kDepthRestoreMain = R"(
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    if (ssamComposite(p).a >= u_threshold) discard;
    gl_FragDepth = texelFetch(u_opaqueDepth, p, 0).r;
}
)";

}  // namespace ssam::glsl
