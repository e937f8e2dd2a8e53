// Both particle programs: the closest-sample scene depth for half-resolution layers
// ([Hathaway 2010] §3.5.1); particle_kernels.hpp closestDepth() computes the same.
float saturateOrZero(float v) { return v > 0.0 ? (v < 1.0 ? v : 1.0) : 0.0; }
float closestDepth(ivec2 p, int stride) {
    stride = clamp(stride, 1, 4);
    ivec2 last = textureSize(u_sceneDepth, 0) - 1;
    float best = texelFetch(u_sceneDepth, min(p * stride, last), 0).r;
    for (int sy = 0; sy < stride; ++sy)
        for (int sx = 0; sx < stride; ++sx) {
            float z = texelFetch(u_sceneDepth, min(p * stride + ivec2(sx, sy), last), 0).r;
            if (u_greaterIsCloser ? z > best : z < best) best = z;
        }
    return best;
}
