// SPDX-License-Identifier: MIT
// Build-time tool: writes the Vulkan variants of SSAM's GLSL (GLSL 4.50 for glslc) from the one
// source ssam::gl uses too (core/glsl/*.glsl): a Vulkan preamble (explicit
// locations, the per-frame uniform block, push constants, descriptor sets) with #defines that map
// the bodies' u_* names onto them, then the shared bodies unchanged. CMake compiles the files to
// SPIR-V with glslc and embeds them (cmake/embed_spirv.cmake); nothing compiles GLSL at run time.
//
//   ssam_vk_glsl_variants OUT_DIR   writes foliage.vert, mask.vert, mask.frag, maskpair.frag, color.frag,
//                                   fullscreen.vert, composite.frag, restore.frag
// The interface (set, binding, push-constant offsets) is the one ssam/src/vk/pipelines.cpp
// creates its layouts for.
#include <cstdio>
#include <fstream>
#include <string>

#include "ssam_glsl.hpp"  // generated from core/glsl/

namespace {

// Set 0, binding 0: what changes per frame (viewProj, the light, the colour reference); the
// push constants: what changes per draw (FoliageProgram::setModel / setBaseColorFactor /
// bindBaseColorTexture). Layout: model at 0, baseColorFactor at 64, hasTexture at 80 (84 bytes).
constexpr const char* kFoliageInterface = R"(#version 450
layout(set = 0, binding = 0, std140) uniform SsamFrame {
    mat4 viewProj;
    vec4 towardLight;
    vec4 lightColor;
    vec4 ambient;
    float alphaReference;
} u_frame;
layout(push_constant, std430) uniform SsamDraw {
    layout(offset = 0) mat4 model;
    layout(offset = 64) vec4 baseColorFactor;
    layout(offset = 80) uint hasTexture;
} u_draw;
#define u_viewProj u_frame.viewProj
#define u_model u_draw.model
#define u_baseColorFactor u_draw.baseColorFactor
#define u_hasTexture (u_draw.hasTexture != 0u)
#define u_alphaReference u_frame.alphaReference
#define u_towardLight u_frame.towardLight.xyz
#define u_lightColor u_frame.lightColor.xyz
#define u_ambient u_frame.ambient.xyz
)";

constexpr const char* kFoliageVertex = R"(layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec2 a_uv;
layout(location = 3) in vec4 a_color;
layout(location = 4) in vec4 a_instance0;
layout(location = 5) in vec4 a_instance1;
layout(location = 6) in vec4 a_instance2;
layout(location = 7) in vec4 a_instance3;
layout(location = 8) in vec4 a_instanceTint;
layout(location = 0) out vec2 v_uv;
layout(location = 2) out vec4 v_color;
)";

// The colour pass's vertex stage passes the normal on; the mask pass's reads none (Vulkan's
// interface matching warns of an output no stage consumes), so there it is a plain variable.
constexpr const char* kNormalOut = "layout(location = 1) out vec3 v_normal;\n";
constexpr const char* kNormalUnused = "vec3 v_normal;\n";

// The fragment side of the same interface. One mask target (RGBA8 / RGBA16F, mask.frag): the
// body's second output is a plain variable; two (Rg16f, maskpair.frag): MAX at 0, ADD at 1.
constexpr const char* kFoliageFragment = R"(layout(set = 1, binding = 0) uniform sampler2D u_baseColor;
layout(location = 0) in vec2 v_uv;
layout(location = 2) in vec4 v_color;
)";

// Set 0: rt_foliage, the mask and the second mask target (the mask again when there is none);
// push constants: maskLerp at 0, squareMask at 4, hasMaskAdd at 8, colorFade at 16, colorBlur at
// 24, foliageClear at 32. Settings::depthMaskThreshold's pass (restore.frag) adds the saved opaque depth at binding 3
// and the threshold at 12 (one push-constant block per shader, hence `extra`, in offset order).
std::string compositeInterface(const char* extra) {
    return std::string(R"(#version 450
#define PRECISE precise
layout(set = 0, binding = 0) uniform sampler2D u_foliage;
layout(set = 0, binding = 1) uniform sampler2D u_mask;
layout(set = 0, binding = 2) uniform sampler2D u_maskAdd;
layout(push_constant, std430) uniform SsamComposite {
    layout(offset = 0) float maskLerp;
    layout(offset = 4) uint squareMask;
    layout(offset = 8) uint hasMaskAdd;
)") + extra +
           R"(    layout(offset = 16) vec2 colorFade;
    layout(offset = 24) uint colorBlur;
    layout(offset = 32) vec3 foliageClear;
} u_composite;
#define u_maskLerp u_composite.maskLerp
#define u_colorFade u_composite.colorFade
#define u_foliageClear u_composite.foliageClear
#define u_colorBlur (u_composite.colorBlur != 0u)
#define u_squareMask (u_composite.squareMask != 0u)
#define u_maskAddBound (u_composite.hasMaskAdd != 0u)
)";
}
constexpr const char* kRestoreExtra = "    layout(offset = 12) float threshold;\n";
constexpr const char* kRestoreInterface = R"(layout(set = 0, binding = 3) uniform sampler2D u_opaqueDepth;
#define u_threshold u_composite.threshold
)";

bool write(const std::string& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary);
    out << text;
    out.close();
    if (!out) {
        std::fprintf(stderr, "ssam_vk_glsl_variants: cannot write %s\n", path.c_str());
        return false;
    }
    return true;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: ssam_vk_glsl_variants OUT_DIR\n");
        return 2;
    }
    const std::string dir = argv[1];
    const std::string foliage = kFoliageInterface;
    const bool ok =
        write(dir + "/foliage.vert", foliage + kFoliageVertex + kNormalOut + ssam::glsl::kFoliageVertexMain) &&
        write(dir + "/mask.vert", foliage + kFoliageVertex + kNormalUnused + ssam::glsl::kFoliageVertexMain) &&
        write(dir + "/mask.frag", foliage + kFoliageFragment +
                                      "layout(location = 0) out vec4 o_mask;\nvec4 o_maskAdd;\n" +
                                      ssam::glsl::kMaskFragmentMain) &&
        write(dir + "/maskpair.frag", foliage + kFoliageFragment +
                                          "layout(location = 0) out vec4 o_mask;\n"
                                          "layout(location = 1) out vec4 o_maskAdd;\n" +
                                          ssam::glsl::kMaskFragmentMain) &&
        write(dir + "/color.frag",
              foliage + kFoliageFragment +
                  "layout(location = 1) in vec3 v_normal;\nlayout(location = 0) out vec4 o_color;\n" +
                  ssam::glsl::kColorFragmentMain) &&
        write(dir + "/fullscreen.vert",
              std::string("#version 450\n#define VERTEX_INDEX gl_VertexIndex\n") + ssam::glsl::kFullscreenVertexMain) &&
        write(dir + "/composite.frag", compositeInterface("") + "layout(location = 0) out vec4 o_color;\n" +
                                           ssam::glsl::kCompositeMask + ssam::glsl::kCompositeBlur +
                                           ssam::glsl::kComposite +
                                           "void main() { o_color = ssamComposite(ivec2(gl_FragCoord.xy)); }\n") &&
        write(dir + "/restore.frag", compositeInterface(kRestoreExtra) + kRestoreInterface +
                                         ssam::glsl::kCompositeMask + ssam::glsl::kCompositeBlur +
                                         ssam::glsl::kComposite + ssam::glsl::kDepthRestoreMain);
    return ok ? 0 : 1;
}
