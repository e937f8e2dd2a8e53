// Every pixel the tint colour (tint_kernel.hpp TintKernel).
void main() {
    finish(vec4(u_color, 1.0));
}
