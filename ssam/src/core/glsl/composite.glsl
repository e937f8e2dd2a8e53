// SPDX-License-Identifier: MIT
// After kCompositeMask; needs u_foliage (sampler2D) too. Defines vec4 ssamComposite(ivec2 pixel).
vec4 ssamComposite(ivec2 p) {
    // A non-finite foliage colour (HDR lighting, hostile data) composites as black.
    vec3 color = texelFetch(u_foliage, p, 0).rgb;
    for (int c = 0; c < 3; ++c)
        if (isnan(color[c]) || isinf(color[c])) color[c] = 0.0;
    return vec4(color, ssamCompositeMask(p));
}
