#version 450
// SPDX-License-Identifier: MIT
// The host's own vertex stage (ssam_vk_host_shaders), used in both of SSAM's foliage passes: the
// wind bends a card's vertex at height h = v by windOffset(wind, h) = wind * h * h in x (common/scene.hpp).
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec2 a_uv;
layout(push_constant, std430) uniform Host {
    mat4 viewProj;
    vec4 tint;  // rgb and the alpha factor
    float wind;
    float alphaReference;  // SSAM's PassInfo::alphaReference
} u;
layout(location = 0) out vec2 v_uv;
void main() {
    float h = a_uv.y;
    gl_Position = u.viewProj * vec4(a_position.x + u.wind * h * h, a_position.yz, 1.0);
    v_uv = a_uv;
}
