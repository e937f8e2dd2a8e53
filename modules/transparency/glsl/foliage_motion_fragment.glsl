// FoliageMotion (transparency/temporal.hpp; soft: foliage_motion_kernel.hpp): the world-space
// motion in the normal slot, and AlphaOnly's saturated alpha for the pipeline's alpha test.
void main() {
    float a = u_alphaFactor * v_color.a;
    if (u_hasTexture) a *= sampleBase(v_uv).a;
    a = a > 0.0 ? (a < 1.0 ? a : 1.0) : 0.0;
    finish(vec4(v_normal, a));
}
