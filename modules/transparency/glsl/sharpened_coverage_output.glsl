// SharpenedCoverageLit's output hook (transparency/sharpened_coverage.hpp; soft:
// sharpened_coverage_kernel.hpp): [Golus 2017]'s alpha rescaled by its fine screen-space
// derivative. SURFACE_OUTPUT is expanded inside the lit surface's main(), in uniform control flow.
// A crossfading batch (lod_dither.glsl) is sharpened without its weight, then its other-level
// pixels are dropped, after the derivative.
#define SURFACE_OUTPUT(c) lodDitherDropped(sharpenedCoverageOutput(lodFadeRemoved(c, v_color.a)), v_color.a)

vec4 sharpenedCoverageOutput(vec4 c) {
    float width = max(fwidthFine(c.a), 1e-4);
    return vec4(c.rgb, clamp((c.a - u_reference) / width + 0.5, 0.0, 1.0));
}
