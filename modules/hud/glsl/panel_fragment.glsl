// OverlayPanel (overlay_kernels.hpp OverlayPanelKernel::shade), integer for integer.
int floorDiv(int a, int b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }
void main() {
    int zoom = max(u_zoom, 1);
    ivec2 p = ivec2(gl_FragCoord.xy);
    ivec2 q = ivec2(u_sourceX + floorDiv(p.x - u_targetX, zoom), u_sourceY + floorDiv(p.y - u_targetY, zoom));
    ivec2 size = textureSize(u_source, 0);
    if (q.x < 0 || q.y < 0 || q.x >= size.x || q.y >= size.y) { finish(vec4(0.0, 0.0, 0.0, 1.0)); return; }
    finish(vec4(texelFetch(u_source, q, 0).rgb, 1.0));
}
