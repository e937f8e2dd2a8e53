// SPDX-License-Identifier: MIT
// After kCompositeMask and kCompositeBlur; needs u_colorFade (vec2), u_foliageClear (vec3),
// u_colorBlur (bool) too. Defines vec4 ssamComposite(ivec2 pixel).

vec4 ssamComposite(ivec2 p) {
    // A non-finite foliage colour (HDR lighting, hostile data) composites as black.
    vec3 color = u_colorBlur ? ssamBlurredFoliage(p) : texelFetch(u_foliage, p, 0).rgb;
    for (int c = 0; c < 3; ++c)
        if (isnan(color[c]) || isinf(color[c])) color[c] = 0.0;
    // Settings::colorFade: the colour fades in from the clear colour as the MAX mask passes the
    // colour pass's reference, so a leaf crossing it changes the pixel continuously.
    if (u_colorFade.y > u_colorFade.x)
        color = mix(u_foliageClear, color, smoothstep(u_colorFade.x, u_colorFade.y, texelFetch(u_mask, p, 0).r));
    return vec4(color, ssamCompositeMask(p));
}
