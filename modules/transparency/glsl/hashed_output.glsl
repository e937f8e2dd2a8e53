// HashedLit's output hook (transparency/hashed_alpha.hpp; soft: hashed_kernel.hpp). SURFACE_OUTPUT
// is expanded inside the lit surface's main(), after v_uv is declared.
// A crossfading instance is dithered first (lod_dither.glsl): its other-level pixels have alpha 0.
#define SURFACE_OUTPUT(c) hashedOutput(lodDitherOutput(c, v_color.a), v_uv)

uvec3 pcg3d(uvec3 v) {
    v = v * 1664525u + 1013904223u;
    v.x += v.y * v.z; v.y += v.z * v.x; v.z += v.x * v.y;
    v ^= v >> 16u;
    v.x += v.y * v.z; v.y += v.z * v.x; v.z += v.x * v.y;
    return v;
}
float hashToUnit(uint h) { return float(h >> 8u) * (1.0 / 16777216.0); }
float log2Mantissa(float m) {
    precise float t = m - 1.0;
    precise float p = ((0.15824871 * t - 0.57561607) * t + 1.41736736) * t;
    return p;
}
uint cellOf(float scaled) {
    float f = floor(scaled);
    float c = f > 1073741824.0 ? 1073741824.0 : (f < -1073741824.0 ? -1073741824.0 : f);
    return uint(int(c));
}
float cellHash(vec2 uv, ivec2 levels, uint seed) {
    float sx = ldexp(1.0, levels.x), sy = ldexp(1.0, levels.y);
    precise float ux = sx * uv.x, uy = sy * uv.y;
    uvec3 key = uvec3(cellOf(ux), cellOf(uy), seed ^ (uint(levels.x) * 0x9e3779b9u) ^ (uint(levels.y) * 0x85ebca6bu));
    return hashToUnit(pcg3d(key).x);
}
void levelsOf(float d, out int floorLevel, out int ceilLevel, out float fraction) {
    if (!(d > 1.1754944e-38)) d = 1.1754944e-38;
    if (!(d < 3.4e38)) d = 3.4e38;
    uint bits = floatBitsToUint(d);
    int exponent = int((bits >> 23u) & 0xffu) - 127;
    float m = log2Mantissa(uintBitsToFloat((bits & 0x007fffffu) | 0x3f800000u));
    int e = exponent < -60 ? -60 : (exponent > 60 ? 60 : exponent);
    ceilLevel = -e;
    floorLevel = m > 0.0 ? -e - 1 : -e;
    fraction = m > 0.0 ? 1.0 - m : 0.0;
}
float uniformFromBlend(float x, float f) {
    precise float a = f < 1.0 - f ? f : 1.0 - f;
    precise float t = x;
    if (x < 1.0 - a) {
        if (x < a) t = (x * x) / (2.0 * a * (1.0 - a));
        else t = (x - 0.5 * a) / (1.0 - a);
    } else {
        t = 1.0 - ((1.0 - x) * (1.0 - x)) / (2.0 * a * (1.0 - a));
    }
    return t > 1e-6 ? (t < 1.0 ? t : 1.0) : 1e-6;
}
float hashedThreshold(vec2 uv, vec2 dx, vec2 dy) {
    uint seed = uint(u_seed);
    precise float x = 0.0, f = 0.0;
    if (!u_anisotropic) {
        precise float lx = sqrt(dx.x * dx.x + dx.y * dx.y), ly = sqrt(dy.x * dy.x + dy.y * dy.y);
        int lo, hi;
        precise float d = u_hashScale * (lx > ly ? lx : ly);
        levelsOf(d, lo, hi, f);
        float h0 = cellHash(uv, ivec2(lo), seed), h1 = cellHash(uv, ivec2(hi), seed);
        x = (1.0 - f) * h0 + f * h1;
    } else {
        float ax = abs(dx.x) > abs(dy.x) ? abs(dx.x) : abs(dy.x);
        float ay = abs(dx.y) > abs(dy.y) ? abs(dx.y) : abs(dy.y);
        ivec2 lo, hi;
        vec2 fr;
        precise float sx = u_hashScale * ax * 1.41421354, sy = u_hashScale * ay * 1.41421354;
        levelsOf(sx, lo.x, hi.x, fr.x);
        levelsOf(sy, lo.y, hi.y, fr.y);
        float h0 = cellHash(uv, lo, seed), h1 = cellHash(uv, hi, seed);
        precise float toLow = sqrt(fr.x * fr.x + fr.y * fr.y);
        precise float toHigh = sqrt((1.0 - fr.x) * (1.0 - fr.x) + (1.0 - fr.y) * (1.0 - fr.y));
        f = toLow / (toLow + toHigh);
        x = (1.0 - f) * h0 + f * h1;
    }
    return uniformFromBlend(x, f);
}
vec4 hashedOutput(vec4 c, vec2 uv) {
    // The analytic derivatives of sampleBase(): uv/w and 1/w are linear in screen space, so
    // their per-quad differences are the plane's gradient up to rounding.
    float inverseW = gl_FragCoord.w;
    vec2 dqdx = dFdx(uv * inverseW), dqdy = dFdy(uv * inverseW);
    float dwdx = dFdx(inverseW), dwdy = dFdy(inverseW);
    float w = 1.0 / inverseW;
    precise vec2 dx = (dqdx - uv * dwdx) * w;
    precise vec2 dy = (dqdy - uv * dwdy) * w;
    float t = hashedThreshold(uv, dx, dy);
    if (u_outputThreshold) return vec4(t, t, t, 1.0);
    return vec4(c.rgb, c.a >= t ? 1.0 : 0.0);
}
