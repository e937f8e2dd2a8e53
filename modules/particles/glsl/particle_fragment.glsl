// Particle (particle_kernels.hpp ParticleKernel).
void main() {
    vec2 q = v_uv * 2.0 - 1.0;
    float shape = saturateOrZero(1.0 - (q.x * q.x + q.y * q.y));
    float fade = 1.0;
    if (u_sceneDepthBound) {
        float z = closestDepth(ivec2(gl_FragCoord.xy), u_depthStride);
        float sceneDistance = u_depthScale / (z + u_depthOffset);
        fade = saturateOrZero((sceneDistance - v_normal.x) / u_softness);
    }
    float a = saturateOrZero(v_color.a) * shape * fade;
    float additive = saturateOrZero(v_normal.y);
    vec4 o = vec4(v_color.rgb * a, a * (1.0 - additive));
    for (int c = 0; c < 4; ++c)
        if (isnan(o[c]) || isinf(o[c])) o[c] = 0.0;
    finish(o);
}
