// OverlayFill (overlay_kernels.hpp OverlayFillKernel): the vertex colour.
void main() {
    finish(v_color);
}
