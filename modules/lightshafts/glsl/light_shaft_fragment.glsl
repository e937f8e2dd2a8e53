// The march of LightShaftKernel (light_shaft_kernel.hpp), sample point for sample point;
// `precise` keeps the compiler from contracting the additions into FMAs, so GL marches
// through the same texels as the soft backend.
float sunGlow(vec2 q) {
    if (!(u_glowRadius > 0.0)) return 1.0;
    float t = max(0.0, 1.0 - length(q - u_sunPixel) / u_glowRadius);
    return t * t;
}
void main() {
    ivec2 size = textureSize(u_depth, 0);
    int samples = clamp(u_samples, 1, 128);
    precise vec2 p = floor(gl_FragCoord.xy) + 0.5;
    precise vec2 step = (u_sunPixel - p) * (u_density / float(samples));
    float sum = 0.0, weight = 1.0;
    for (int i = 0; i < samples; ++i) {
        precise vec2 q = p + step * float(i);
        if (!(q.x >= 0.0 && q.y >= 0.0 && q.x < float(size.x) && q.y < float(size.y))) break;
        float z = texelFetch(u_depth, ivec2(q), 0).r;
        bool sky = u_greaterIsCloser ? !(z > u_farDepth) : !(z < u_farDepth);
        if (sky) sum += weight * sunGlow(q);
        weight *= u_decay;
    }
    vec3 c = u_color * (u_intensity * sum / float(samples));
    for (int i = 0; i < 3; ++i)
        if (isnan(c[i]) || isinf(c[i])) c[i] = 0.0;
    finish(vec4(c, 0.0));
}
