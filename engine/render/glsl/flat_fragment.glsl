// Flat (soft: kernel/programs.hpp).
void main() {
    finish(u_color * v_color);
}
