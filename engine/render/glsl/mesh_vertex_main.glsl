// The mesh vertex stage. Positions are computed with the soft backend's float operations in its
// order (glm: mvp = viewProj * model column by column, then (c0*x + c1*y) + (c2*z + c3*w));
// `precise` forbids FMA contraction and reassociation, so the clip positions, and with them the
// snapped vertices, agree bit for bit.
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec2 a_uv;
layout(location = 3) in vec4 a_color;
layout(location = 4) in vec4 a_model0;
layout(location = 5) in vec4 a_model1;
layout(location = 6) in vec4 a_model2;
layout(location = 7) in vec4 a_model3;
layout(location = 8) in vec4 a_tint;

vec4 mulColumn(mat4 a, vec4 b) {
    precise vec4 r = a[0] * b.x + a[1] * b.y + a[2] * b.z + a[3] * b.w;
    return r;
}

void main() {
    mat4 model = mat4(a_model0, a_model1, a_model2, a_model3);
    mat4 mvp = mat4(mulColumn(u_viewProj, model[0]), mulColumn(u_viewProj, model[1]),
                    mulColumn(u_viewProj, model[2]), mulColumn(u_viewProj, model[3]));
    precise vec4 xy = mvp[0] * a_position.x + mvp[1] * a_position.y;
    precise vec4 zw = mvp[2] * a_position.z + mvp[3];
    precise vec4 clip = xy + zw;
    gl_Position = clip;
    v_uv = a_uv;
    v_normal = mat3(model) * a_normal;
    v_color = a_color * a_tint;
    v_instance = INSTANCE_INDEX;
}
