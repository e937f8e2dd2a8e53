// SPDX-License-Identifier: MIT
// Settings::depthMaskThreshold (ssam::gl and ssam::vk): the composite's mask (the function above)
// against the threshold; below it the opaque depth saved before the colour pass goes back.
// Needs kCompositeMask's and kComposite's names and u_opaqueDepth (sampler2D), u_threshold (float).
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    if (ssamComposite(p).a >= u_threshold) discard;
    gl_FragDepth = texelFetch(u_opaqueDepth, p, 0).r;
}
