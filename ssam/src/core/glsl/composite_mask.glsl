// SPDX-License-Identifier: MIT
// The composite's mask (§3.5.4, Listing 3.2; §3.6.2). Needs u_mask, u_maskAdd (sampler2D),
// u_maskAddBound, u_squareMask (bool), u_maskLerp (float). Defines float ssamCompositeMask(ivec2).
float ssamCompositeMask(ivec2 p) {
    vec4 m = texelFetch(u_mask, p, 0);
    float addMask = u_maskAddBound ? texelFetch(u_maskAdd, p, 0).r : m.a;
    PRECISE float blend = m.r + (addMask - m.r) * u_maskLerp;
    blend = blend > 0.0 ? (blend < 1.0 ? blend : 1.0) : 0.0;  // NaN -> 0
    if (u_squareMask) blend *= blend;  // the squared alpha trick ([Hathaway 2010] §3.6.2)
    return blend;
}
