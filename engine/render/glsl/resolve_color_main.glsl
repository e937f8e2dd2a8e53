layout(location = 0) out vec4 o_color;
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    precise vec4 sum = vec4(0.0);
    for (int s = 0; s < u_samples; ++s) sum += texelFetch(u_source, p, s);
    precise vec4 average = sum / float(u_samples);
    o_color = average;
}
