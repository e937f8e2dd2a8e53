// SSAM+'s blurred composite: the colour SSAM's colorBlur takes (ssam's composite_blur.glsl) over
// the front layers, SSAM+'s coverage.
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec3 color = withFrontLayers(p, ssamBlurredFoliage(p));
    for (int c = 0; c < 3; ++c)
        if (isnan(color[c]) || isinf(color[c])) color[c] = 0.0;
    finish(vec4(color, layerCoverage(p)));
}
