// The dithered level-of-detail crossfade (transparency/lod_dither.hpp, which says why; soft:
// the same functions there). `w` is the interpolated vertex colour's alpha, the instance's
// crossfade weight; u_lodDither is LodDither (0 off, 1 keep below, 2 keep above).
const float kLodBayer4[16] = float[16](0.0, 8.0, 2.0, 10.0, 12.0, 4.0, 14.0, 6.0, 3.0, 11.0, 1.0, 9.0, 15.0, 7.0,
                                       13.0, 5.0);

bool lodDitherKeeps(float w) {
    if (u_lodDither == 0) return true;
    ivec2 p = ivec2(gl_FragCoord.xy) & 3;
    float threshold = (kLodBayer4[p.y * 4 + p.x] + 0.5) / 16.0;
    return u_lodDither == 1 ? threshold < w : threshold >= 1.0 - w;
}
vec4 lodFadeRemoved(vec4 c, float w) { return u_lodDither == 0 ? c : vec4(c.rgb, c.a / w); }
vec4 lodDitherDropped(vec4 c, float w) { return lodDitherKeeps(w) ? c : vec4(c.rgb, 0.0); }
vec4 lodDitherOutput(vec4 c, float w) { return lodDitherDropped(lodFadeRemoved(c, w), w); }
