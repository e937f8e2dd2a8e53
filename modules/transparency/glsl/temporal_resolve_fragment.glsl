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
// temporal_kernel.hpp previousOf: the pixel's previous position * w, moved by the motion mv when moved.
vec4 previousOf(ivec2 p, float d, bool moved, vec4 mv) {
    precise float px = float(p.x) + 0.5, py = float(p.y) + 0.5;
    precise vec4 q = ((u_reprojection[0] * px + u_reprojection[1] * py) + u_reprojection[2] * d) + u_reprojection[3];
    if (moved) {
        precise float w = ((u_worldW.x * px + u_worldW.y * py) + u_worldW.z * d) + u_worldW.w;
        precise vec4 m =
            ((u_previousToPixels[0] * mv.x + u_previousToPixels[1] * mv.y) + u_previousToPixels[2] * mv.z) * w;
        q = q + m;
    }
    return q;
}
const ivec2 kNeighbours[9] = ivec2[9](ivec2(0, 0), ivec2(-1, -1), ivec2(0, -1), ivec2(1, -1), ivec2(-1, 0),
                                      ivec2(1, 0), ivec2(-1, 1), ivec2(0, 1), ivec2(1, 1));
// temporal_kernel.hpp previousPosition: the nearest moving surface of the 3x3 pixels, the centre first.
vec2 previousPosition(ivec2 p, float d) {
    ivec2 best = ivec2(0);
    float bd = d;
    vec4 bmv = vec4(0.0);
    bool found = false;
    if (u_motionBound) {
        ivec2 size = textureSize(u_motion, 0);
        for (int k = 0; k < 9; ++k) {
            ivec2 n = p + kNeighbours[k];
            if (n.x < 0 || n.y < 0 || n.x >= size.x || n.y >= size.y) continue;
            vec4 mv = texelFetch(u_motion, n, 0);
            if (!(mv.a > 0.0)) continue;
            float nd = texelFetch(u_depth, n, 0).r;
            if (found && !(u_reverseDepth ? nd > bd : nd < bd)) continue;
            found = true;
            best = kNeighbours[k];
            bd = nd;
            bmv = mv;
        }
    }
    if (found && best != ivec2(0)) {
        precise vec4 q = previousOf(p + best, bd, true, bmv);
        precise float ox = q.x / q.w - (float(p.x + best.x) + 0.5), oy = q.y / q.w - (float(p.y + best.y) + 0.5);
        precise vec2 r = vec2((float(p.x) + 0.5) + ox, (float(p.y) + 0.5) + oy);
        return r;
    }
    precise vec4 q = previousOf(p, d, found, bmv);
    precise vec2 r = vec2(q.x / q.w, q.y / q.w);
    return r;
}
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec4 c = at(u_current, p);
    if (u_copyOnly || !u_hasHistory || !u_depthBound || !u_historyBound) {
        finish(c);
        return;
    }
    float d = texelFetch(u_depth, p, 0).r;
    precise vec2 previous = previousPosition(p, d);
    precise float hx = previous.x, hy = previous.y;
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
