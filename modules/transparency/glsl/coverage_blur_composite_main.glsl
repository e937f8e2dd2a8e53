// SSAM+'s blurred composite (soft: program_kernels.hpp CoverageBlurCompositeKernel, summed in
// the same order).
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    ivec2 size = textureSize(u_foliage, 0);
    vec3 sum = vec3(0.0);
    float weights = 0.0;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            ivec2 q = p + ivec2(dx, dy);
            if (q.x < 0 || q.y < 0 || q.x >= size.x || q.y >= size.y) continue;
            vec4 c = texelFetch(u_foliage, q, 0);
            if (!(c.a > 0.0)) continue;
            float weight = float((2 - dx * dx) * (2 - dy * dy));
            sum += weight * c.rgb;
            weights += weight;
        }
    vec3 color = weights > 0.0 ? sum / weights : texelFetch(u_foliage, p, 0).rgb;
    for (int c = 0; c < 3; ++c)
        if (isnan(color[c]) || isinf(color[c])) color[c] = 0.0;
    finish(vec4(color, layerCoverage(p)));
}
