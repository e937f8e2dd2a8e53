#version 450
// SPDX-License-Identifier: MIT
// The mist's colour, blended by the pipeline (SRC_ALPHA, ONE_MINUS_SRC_ALPHA; the frame's alpha kept).
layout(push_constant, std430) uniform Mist {
    mat4 viewProj;
    vec4 rect;
    vec4 color;
    float z;
} u;
layout(location = 0) out vec4 o_color;
void main() { o_color = u.color; }
