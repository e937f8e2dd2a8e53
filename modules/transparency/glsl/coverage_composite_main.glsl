// SSAM+'s composite (soft: program_kernels.hpp CoverageCompositeKernel): the kept leaf's colour over
// the front layers, SSAM+'s coverage.
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec3 color = withFrontLayers(p, texelFetch(u_foliage, p, 0).rgb);
    for (int c = 0; c < 3; ++c)
        if (isnan(color[c]) || isinf(color[c])) color[c] = 0.0;
    finish(vec4(color, layerCoverage(p)));
}
