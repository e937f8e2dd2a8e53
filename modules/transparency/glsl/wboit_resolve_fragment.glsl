// The WBOIT composite (McGuire & Bavoil 2013): average colour and revealage; the blend
// (INV_SRC_ALPHA / SRC_ALPHA) puts it over the opaque colour.
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec4 sum = texelFetch(u_accumulation, p, 0);
    float reveal = clamp01(texelFetch(u_revealage, p, 0).r);
    float weight = sum.a > 1e-5 ? sum.a : 1e-5;
    vec3 average = sum.rgb / weight;
    for (int c = 0; c < 3; ++c)
        if (isnan(average[c]) || isinf(average[c])) average[c] = 0.0;
    finish(vec4(average, reveal));
}
