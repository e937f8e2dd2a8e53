// WboitAccumulate: the lit surface's output hook wboitWeighted() (soft: program_kernels.hpp
// wboitWeight, the same operations in the same order). McGuire & Bavoil 2013, eq. (7), with
// the view depth |z| = clip w = 1 / gl_FragCoord.w.
#define SURFACE_OUTPUT wboitWeighted
vec4 wboitWeighted(vec4 c) {
    precise float z = abs((1.0 / gl_FragCoord.w) * u_depthScale);
    precise float near = z / 5.0, far = z / 200.0;
    precise float far2 = far * far;
    precise float g = 10.0 / (1e-5 + near * near + far2 * far2 * far2);
    precise float w = c.a * (g > 1e-2 ? (g < 3e3 ? g : 3e3) : 1e-2);
    precise float aw = c.a * w;
    return vec4(c.rgb * aw, aw);
}
