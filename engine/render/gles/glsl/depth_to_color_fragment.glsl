#version 300 es
// The GLES driver's readback of a depth texture: its stored values into an R32F target, which
// glReadPixels can read (ES 3.00 §4.3.2 reads colour buffers only).
precision highp float;
uniform highp sampler2D u_source;
layout(location = 0) out vec4 o_color;
void main() {
    o_color = vec4(texelFetch(u_source, ivec2(gl_FragCoord.xy), 0).r, 0.0, 0.0, 1.0);
}
