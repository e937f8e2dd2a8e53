// SPDX-License-Identifier: MIT
// §3.5.3: alpha test at the colour reference (pass when alpha >= reference, as
// AlphaTest::discardBelow), double-sided lighting (back faces use the flipped normal). Needs the
// mask pass's names and u_alphaReference (float), u_towardLight, u_lightColor, u_ambient (vec3),
// v_normal; writes o_color.
void main() {
    vec4 base = u_baseColorFactor * v_color;
    if (u_hasTexture) base *= texture(u_baseColor, v_uv);
    if (!(base.a >= u_alphaReference)) discard;
    vec3 n = gl_FrontFacing ? v_normal : -v_normal;
    float len = length(n);
    float lambert = len > 0.0 ? max(dot(n / len, u_towardLight), 0.0) : 0.0;
    o_color = vec4(base.rgb * (u_ambient + u_lightColor * lambert), base.a);
}
