// SPDX-License-Identifier: MIT
// Needs u_viewProj, u_model (mat4), a_position, a_normal (vec3), a_uv (vec2), a_color,
// a_instance0..3, a_instanceTint (vec4); writes gl_Position, v_uv, v_normal, v_color. The tint
// multiplies the colour per instance, as the engine's mesh stage does: a level-of-detail
// crossfade puts each level's weight in its alpha and blends through the mask, sort-free.
void main() {
    mat4 model = u_model * mat4(a_instance0, a_instance1, a_instance2, a_instance3);
    gl_Position = u_viewProj * (model * vec4(a_position, 1.0));
    v_uv = a_uv;
    v_normal = mat3(model) * a_normal;
    v_color = a_color * a_instanceTint;
}
