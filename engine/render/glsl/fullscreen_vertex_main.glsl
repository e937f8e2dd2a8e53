// One triangle covering the viewport, no vertex input.
void main() {
    vec2 p = vec2(float((VERTEX_INDEX & 1) << 2) - 1.0, float((VERTEX_INDEX & 2) << 1) - 1.0);
    gl_Position = vec4(p, 0.0, 1.0);
}
