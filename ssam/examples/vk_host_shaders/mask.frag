#version 450
// SPDX-License-Identifier: MIT
// The host's mask pass (ssam::gl's host-shader contract, ssam/gl/ssam_gl.hpp): the coverage alpha,
// saturated, in every channel; no alpha test.
layout(set = 0, binding = 0) uniform sampler2D u_leaf;
layout(push_constant, std430) uniform Host {
    mat4 viewProj;
    vec4 tint;
    float wind;
    float alphaReference;
} u;
layout(location = 0) in vec2 v_uv;
layout(location = 0) out vec4 o_mask;
void main() {
    float a = clamp(u.tint.a * texture(u_leaf, v_uv).a, 0.0, 1.0);
    o_mask = vec4(a);
}
