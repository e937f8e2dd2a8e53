// SPDX-License-Identifier: MIT
// The engine-hosted SSAM's depth restore (foliage_depth_program.hpp), the lit surface's
// SURFACE_OUTPUT: MaskedLit's output, discarded where the composited mask (composite_mask.glsl) is
// below the threshold. Needs u_threshold (float).
vec4 foliageDepthOutput(vec4 c) {
    if (!(ssamCompositeMask(ivec2(gl_FragCoord.xy)) >= u_threshold)) discard;
    return c;
}
