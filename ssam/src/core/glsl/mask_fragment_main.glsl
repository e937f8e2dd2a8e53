// SPDX-License-Identifier: MIT
// [Hathaway 2010] Listing 3.1 / §3.5.2: only the alpha (no lighting, no colour fetch), saturated and
// replicated to every channel of both draw buffers (RG16F precision: MAX target, ADD target).
// Nothing is rejected: the mask pass's alpha reference is 0. Needs u_baseColorFactor (vec4),
// u_hasTexture (bool), u_baseColor (sampler2D), v_uv, v_color; writes o_mask, o_maskAdd.
void main() {
    float a = u_baseColorFactor.a * v_color.a;
    if (u_hasTexture) a *= texture(u_baseColor, v_uv).a;
    a = clamp(a, 0.0, 1.0);
    o_mask = vec4(a);
    o_maskAdd = vec4(a);
}
