#version 450
// SPDX-License-Identifier: MIT
// The host's colour pass (the host-shader contract): straight (rgb, a), fragments with
// !(a >= alphaReference) discarded; unlit, as SSAM's built-in program with its default light.
layout(set = 0, binding = 0) uniform sampler2D u_leaf;
layout(push_constant, std430) uniform Host {
    mat4 viewProj;
    vec4 tint;
    float wind;
    float alphaReference;
} u;
layout(location = 0) in vec2 v_uv;
layout(location = 0) out vec4 o_color;
void main() {
    vec4 base = u.tint * texture(u_leaf, v_uv);
    if (!(base.a >= u.alphaReference)) discard;
    o_color = base;
}
