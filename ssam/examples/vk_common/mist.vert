#version 450
// SPDX-License-Identifier: MIT
// The host's transparent pass (--mist: common/scene.hpp's kMist): one world-space rectangle at one
// depth, its corners from the vertex index (a triangle strip of four), through the scene's
// view-projection.
layout(push_constant, std430) uniform Mist {
    mat4 viewProj;
    vec4 rect;   // x0, y0, x1, y1
    vec4 color;  // straight alpha
    float z;
} u;
void main() {
    vec2 corner = vec2(float(gl_VertexIndex & 1), float(gl_VertexIndex >> 1));
    gl_Position = u.viewProj * vec4(mix(u.rect.xy, u.rect.zw, corner), u.z, 1.0);
}
