// The lit surface (OpaqueLit, MaskedLit; soft: kernel/programs.hpp SurfaceProgram); glsl/lit_surface.hpp says what goes before it.
// u_towardLight is normalised on the CPU, as glm::normalize does in the soft backend
// (UniformType::Direction).

vec4 toStraight(vec4 t) {
    if (!u_premultiplied || !(t.a > 0.0)) return t;
    return vec4(t.rgb / t.a, t.a);
}

float lambert(vec3 n) {
    float len = length(n);
    if (!(len > 0.0)) return 0.0;
    return max(dot(n / len, u_towardLight), 0.0);
}

void main() {
    vec4 base = u_color * v_color;
    if (u_hasTexture) base *= toStraight(sampleBase(v_uv));
    vec3 n = v_normal;
#if ALPHA_MASKED
    if (!gl_FrontFacing) n = -n;  // double-sided: back faces lit with the flipped normal
#endif
    vec3 lit = base.rgb * (u_ambient + u_lightColor * lambert(n));
#if ALPHA_MASKED
#ifdef SURFACE_OUTPUT
    finish(SURFACE_OUTPUT(vec4(lit, base.a)));
#else
    finish(vec4(lit, base.a));
#endif
#else
    finish(vec4(lit, 1.0));
#endif
}
