// SPDX-License-Identifier: MIT
#pragma once
// The GLSL bodies of SSAM's built-in foliage programs and of its full-screen triangle, one
// source for ssam::gl (GLSL 3.30, loose uniforms: gl/shaders.cpp) and ssam::vk (GLSL 4.50 for
// SPIR-V, push constants and a uniform block: vk/glsl_variants.cpp). Each declares the inputs,
// outputs and u_* names the way its API allows (ssam::vk maps the u_* names onto its blocks with
// #defines) and appends these bodies, so the formulas exist once.
namespace ssam::glsl {

// Needs u_viewProj, u_model (mat4), a_position, a_normal (vec3), a_uv (vec2), a_color,
// a_instance0..3 (vec4); writes gl_Position, v_uv, v_normal, v_color.
inline constexpr const char* kFoliageVertexMain = R"(void main() {
    mat4 model = u_model * mat4(a_instance0, a_instance1, a_instance2, a_instance3);
    gl_Position = u_viewProj * (model * vec4(a_position, 1.0));
    v_uv = a_uv;
    v_normal = mat3(model) * a_normal;
    v_color = a_color;
}
)";

// [Hathaway 2010] Listing 3.1 / §3.5.2: only the alpha (no lighting, no colour fetch), saturated and
// replicated to every channel of both draw buffers (RG16F precision: MAX target, ADD target).
// Nothing is rejected: the mask pass's alpha reference is 0. Needs u_baseColorFactor (vec4),
// u_hasTexture (bool), u_baseColor (sampler2D), v_uv, v_color; writes o_mask, o_maskAdd.
inline constexpr const char* kMaskFragmentMain = R"(void main() {
    float a = u_baseColorFactor.a * v_color.a;
    if (u_hasTexture) a *= texture(u_baseColor, v_uv).a;
    a = clamp(a, 0.0, 1.0);
    o_mask = vec4(a);
    o_maskAdd = vec4(a);
}
)";

// §3.5.3: alpha test at the colour reference (pass when alpha >= reference, as
// AlphaTest::discardBelow), double-sided lighting (back faces use the flipped normal). Needs the
// mask pass's names and u_alphaReference (float), u_towardLight, u_lightColor, u_ambient (vec3),
// v_normal; writes o_color.
inline constexpr const char* kColorFragmentMain = R"(void main() {
    vec4 base = u_baseColorFactor * v_color;
    if (u_hasTexture) base *= texture(u_baseColor, v_uv);
    if (!(base.a >= u_alphaReference)) discard;
    vec3 n = gl_FrontFacing ? v_normal : -v_normal;
    float len = length(n);
    float lambert = len > 0.0 ? max(dot(n / len, u_towardLight), 0.0) : 0.0;
    o_color = vec4(base.rgb * (u_ambient + u_lightColor * lambert), base.a);
}
)";

// One triangle over the whole viewport from the vertex index (VERTEX_INDEX: gl_VertexID in GL,
// gl_VertexIndex in Vulkan).
inline constexpr const char* kFullscreenVertexMain = R"(void main() {
    vec2 p = vec2(float((VERTEX_INDEX & 1) << 2) - 1.0, float((VERTEX_INDEX & 2) << 1) - 1.0);
    gl_Position = vec4(p, 0.0, 1.0);
}
)";

}  // namespace ssam::glsl
