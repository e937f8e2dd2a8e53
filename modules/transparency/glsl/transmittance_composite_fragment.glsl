// The exact reference's composite (soft: program_kernels.hpp TransmittanceCompositeKernel).
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec3 color = texelFetch(u_color, p, 0).rgb;
    for (int c = 0; c < 3; ++c)
        if (isnan(color[c]) || isinf(color[c])) color[c] = 0.0;
    finish(vec4(color, clamp01(texelFetch(u_transmittance, p, 0).r)));
}
