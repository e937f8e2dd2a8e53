// SPDX-License-Identifier: MIT
#include "shaders.hpp"

#include "../composite_glsl.hpp"

namespace ssam::gl::shaders {

// The host's attribute locations (Settings::attributes) written into the layout qualifiers, so
// the host's own VAOs are read as they are. Unset attributes read the generic values SSAM sets
// before each pass (identity instance model, white colour).
std::string foliageVertex(const AttributeLocations& at) {
    auto in = [](unsigned int location, const char* declaration) {
        return "layout(location = " + std::to_string(location) + ") in " + declaration + ";\n";
    };
    return "#version 330 core\n" + in(at.position, "vec3 a_position") + in(at.normal, "vec3 a_normal") +
           in(at.uv, "vec2 a_uv") + in(at.color, "vec4 a_color") + in(at.instanceModel, "vec4 a_instance0") +
           in(at.instanceModel + 1, "vec4 a_instance1") + in(at.instanceModel + 2, "vec4 a_instance2") +
           in(at.instanceModel + 3, "vec4 a_instance3") + R"(uniform mat4 u_viewProj;
uniform mat4 u_model;
out vec2 v_uv;
out vec3 v_normal;
out vec4 v_color;
void main() {
    mat4 model = u_model * mat4(a_instance0, a_instance1, a_instance2, a_instance3);
    gl_Position = u_viewProj * (model * vec4(a_position, 1.0));
    v_uv = a_uv;
    v_normal = mat3(model) * a_normal;
    v_color = a_color;
}
)";
}

// [Hathaway 2010] Listing 3.1 / §3.5.2: only the alpha (no lighting, no colour fetch), saturated and
// replicated to every channel of both draw buffers (RG16F precision: MAX target, ADD target).
// Nothing is rejected: the mask pass's alpha reference is 0.
const char* const kMaskFragment = R"(#version 330 core
in vec2 v_uv;
in vec4 v_color;
uniform vec4 u_baseColorFactor;
uniform bool u_hasTexture;
uniform sampler2D u_baseColor;
layout(location = 0) out vec4 o_mask;
layout(location = 1) out vec4 o_maskAdd;
void main() {
    float a = u_baseColorFactor.a * v_color.a;
    if (u_hasTexture) a *= texture(u_baseColor, v_uv).a;
    a = clamp(a, 0.0, 1.0);
    o_mask = vec4(a);
    o_maskAdd = vec4(a);
}
)";

// §3.5.3: alpha test at the colour reference (pass when alpha >= reference, as
// AlphaTest::discardBelow), double-sided lighting (back faces use the flipped normal).
const char* const kColorFragment = R"(#version 330 core
in vec2 v_uv;
in vec3 v_normal;
in vec4 v_color;
uniform vec4 u_baseColorFactor;
uniform bool u_hasTexture;
uniform sampler2D u_baseColor;
uniform float u_alphaReference;
uniform vec3 u_towardLight;
uniform vec3 u_lightColor;
uniform vec3 u_ambient;
layout(location = 0) out vec4 o_color;
void main() {
    vec4 base = u_baseColorFactor * v_color;
    if (u_hasTexture) base *= texture(u_baseColor, v_uv);
    if (!(base.a >= u_alphaReference)) discard;
    vec3 n = gl_FrontFacing ? v_normal : -v_normal;
    float len = length(n);
    float lambert = len > 0.0 ? max(dot(n / len, u_towardLight), 0.0) : 0.0;
    o_color = vec4(base.rgb * (u_ambient + u_lightColor * lambert), base.a);
}
)";

const char* const kFullscreenVertex = R"(#version 330 core
void main() {
    vec2 p = vec2(float((gl_VertexID & 1) << 2) - 1.0, float((gl_VertexID & 2) << 1) - 1.0);
    gl_Position = vec4(p, 0.0, 1.0);
}
)";

// §3.5.4 / Listing 3.2, one texel per pixel: the same function as the engine backend's
// composite program (composite_glsl.hpp); the output (foliage, mask) is blended SRC_ALPHA /
// ONE_MINUS_SRC_ALPHA onto the engine's colour, which is lerp(opaque, foliage, mask) and keeps
// the colour's alpha. GLSL 3.30 has no `precise`; nothing here can be contracted into an FMA
// that changes which side of 0 or 1 the mask falls anyway.
const std::string kCompositeHead = std::string(R"(#version 330 core
#define PRECISE
uniform sampler2D u_foliage;
uniform sampler2D u_mask;
uniform sampler2D u_maskAdd;
uniform bool u_hasMaskAdd;
uniform float u_maskLerp;
uniform bool u_squareMask;
)") + ssam::glsl::kComposite;

const std::string kCompositeFragment = kCompositeHead + R"(
layout(location = 0) out vec4 o_color;
void main() { o_color = ssamComposite(ivec2(gl_FragCoord.xy)); }
)";

}  // namespace ssam::gl::shaders
