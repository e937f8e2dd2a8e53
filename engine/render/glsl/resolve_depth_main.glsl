void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    float best = texelFetch(u_source, p, 0).r;
    for (int s = 1; s < u_samples; ++s) {
        float z = texelFetch(u_source, p, s).r;
        if (u_greater != 0 ? z > best : z < best) best = z;
    }
    gl_FragDepth = best;
}
