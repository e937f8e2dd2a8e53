// TemporalResolve (transparency/temporal.hpp; soft: temporal_kernel.hpp).
vec4 finiteOf(vec4 c) {
    for (int i = 0; i < 4; ++i)
        if (isnan(c[i]) || isinf(c[i])) c[i] = 0.0;
    return c;
}
vec4 at(sampler2D t, ivec2 p) {
    ivec2 size = textureSize(t, 0);
    return finiteOf(texelFetch(t, clamp(p, ivec2(0), size - 1), 0));
}
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec4 c = at(u_current, p);
    if (u_copyOnly || !u_hasHistory || !u_depthBound || !u_historyBound) {
        finish(c);
        return;
    }
    float d = texelFetch(u_depth, p, 0).r;
    precise float px = float(p.x) + 0.5, py = float(p.y) + 0.5;
    precise vec4 q = ((u_reprojection[0] * px + u_reprojection[1] * py) + u_reprojection[2] * d) + u_reprojection[3];
    precise float hx = q.x / q.w, hy = q.y / q.w;
    vec2 size = vec2(textureSize(u_history, 0));
    if (!(hx >= 0.0 && hx <= size.x && hy >= 0.0 && hy <= size.y)) {
        finish(c);
        return;
    }
    precise float sx = hx - 0.5, sy = hy - 0.5;
    float x0 = floor(sx), y0 = floor(sy);
    precise float fx = sx - x0, fy = sy - y0;
    ivec2 i0 = ivec2(int(x0), int(y0));
    precise vec4 top = at(u_history, i0) * (1.0 - fx) + at(u_history, i0 + ivec2(1, 0)) * fx;
    precise vec4 bottom = at(u_history, i0 + ivec2(0, 1)) * (1.0 - fx) + at(u_history, i0 + ivec2(1, 1)) * fx;
    precise vec4 hist = top * (1.0 - fy) + bottom * fy;
    vec4 lo = c, hi = c;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            vec4 n = at(u_current, p + ivec2(dx, dy));
            lo = min(lo, n);
            hi = max(hi, n);
        }
    vec4 clamped = min(max(hist, lo), hi);
    precise vec4 result = clamped + (c - clamped) * u_blend;
    finish(result);
}
