// SPDX-License-Identifier: MIT
#include "shaders.hpp"

#include "gl_functions.hpp"
#include "gl_objects.hpp"
#include "ssam/core/passes.hpp"
#include "ssam_glsl.hpp"  // generated from core/glsl/

namespace ssam::gl::shaders {

// One source per program for both APIs: only the first lines differ. ES 3.00 §4.5.4 gives float
// no default precision in fragment shaders and sampler2D lowp; highp is what desktop GL computes
// in and what WebGL2 guarantees in both stages (an RGBA16F mask read at lowp would lose its sums).
const char* glslHead(const detail::GlFunctions& gl) {
    return gl.es ? "#version 300 es\nprecision highp float;\nprecision highp int;\nprecision highp sampler2D;\n"
                 : "#version 330 core\n";
}

// The host's attribute locations (initialize(), setAttributeLocations()) written into the layout qualifiers, so
// the host's own VAOs are read as they are. Unset attributes read the generic values SSAM sets
// before each pass (identity instance model, white colour and tint).
std::string foliageVertex(const AttributeLocations& at) {
    auto in = [](unsigned int location, const char* declaration) {
        return "layout(location = " + std::to_string(location) + ") in " + declaration + ";\n";
    };
    return in(at.position, "vec3 a_position") + in(at.normal, "vec3 a_normal") + in(at.uv, "vec2 a_uv") +
           in(at.color, "vec4 a_color") + in(at.instanceModel, "vec4 a_instance0") +
           in(at.instanceModel + 1, "vec4 a_instance1") + in(at.instanceModel + 2, "vec4 a_instance2") +
           in(at.instanceModel + 3, "vec4 a_instance3") + in(at.instanceTint, "vec4 a_instanceTint") +
           R"(uniform mat4 u_viewProj;
uniform mat4 u_model;
out vec2 v_uv;
out vec3 v_normal;
out vec4 v_color;
)" + ssam::glsl::kFoliageVertexMain;
}

// The formulas are ssam::glsl's (core/glsl/*.glsl), shared with ssam::vk.
const std::string kMaskFragment = std::string(R"(in vec2 v_uv;
in vec4 v_color;
uniform vec4 u_baseColorFactor;
uniform bool u_hasTexture;
uniform sampler2D u_baseColor;
layout(location = 0) out vec4 o_mask;
layout(location = 1) out vec4 o_maskAdd;
)") + ssam::glsl::kMaskFragmentMain;

const std::string kColorFragment = std::string(R"(in vec2 v_uv;
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
)") + ssam::glsl::kColorFragmentMain;

const std::string kFullscreenVertex =
    std::string("#define VERTEX_INDEX gl_VertexID\n") + ssam::glsl::kFullscreenVertexMain;

// §3.5.4 / Listing 3.2, one texel per pixel: the same function as the engine backend's
// composite program (core/glsl/composite*.glsl); the output (foliage, mask) is blended SRC_ALPHA /
// ONE_MINUS_SRC_ALPHA onto the engine's colour, which is lerp(opaque, foliage, mask) and keeps
// the colour's alpha. GLSL 3.30 and ES 3.00 have no `precise`; nothing here can be contracted into an FMA
// that changes which side of 0 or 1 the mask falls anyway.
const std::string kCompositeHead = std::string(R"(#define PRECISE
uniform sampler2D u_foliage;
uniform sampler2D u_mask;
uniform sampler2D u_maskAdd;
uniform bool u_maskAddBound;
uniform float u_maskLerp;
uniform bool u_squareMask;
uniform vec2 u_colorFade;
uniform vec3 u_foliageClear;
uniform bool u_colorBlur;
)") + ssam::glsl::kCompositeMask + ssam::glsl::kCompositeBlur +
                                   ssam::glsl::kComposite;

const std::string kCompositeFragment = kCompositeHead + R"(
layout(location = 0) out vec4 o_color;
void main() { o_color = ssamComposite(ivec2(gl_FragCoord.xy)); }
)";

void CompositeInputs::locate(const detail::GlFunctions& gl, unsigned int program) {
    detail::locateUniforms(gl, program,
                           {{&foliage, "u_foliage"},
                            {&mask, "u_mask"},
                            {&maskAdd, "u_maskAdd"},
                            {&hasMaskAdd, "u_maskAddBound"},
                            {&maskLerp, "u_maskLerp"},
                            {&square, "u_squareMask"},
                            {&colorFade, "u_colorFade"},
                            {&foliageClear, "u_foliageClear"},
                            {&colorBlur, "u_colorBlur"}});
}

void CompositeInputs::set(const detail::GlFunctions& gl, int foliageUnit, bool withMaskAdd,
                          const Settings& settings) const {
    gl.Uniform1i(foliage, foliageUnit);
    gl.Uniform1i(mask, 1);
    gl.Uniform1i(maskAdd, 2);
    gl.Uniform1i(hasMaskAdd, withMaskAdd ? 1 : 0);
    gl.Uniform1f(maskLerp, settings.maskLerp);
    gl.Uniform1i(square, settings.squareMask ? 1 : 0);
    const core::ColorFade fade = core::colorFadeOf(settings);
    gl.Uniform2f(colorFade, fade.start, fade.end);
    gl.Uniform3fv(foliageClear, 1, fade.clearColor);
    gl.Uniform1i(colorBlur, settings.colorBlur ? 1 : 0);
}

}  // namespace ssam::gl::shaders
