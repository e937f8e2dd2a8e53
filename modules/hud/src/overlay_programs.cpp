// SPDX-License-Identifier: MIT
#include "hud/overlay_programs.hpp"

#include <cstddef>
#include <string>

#include "engine/render/kernel/program_kernel.hpp"
#include "overlay_kernels.hpp"

namespace hud {
namespace {

using namespace engine::render;

constexpr const char* kFillFragment = R"(
void main() {
    finish(v_color);
}
)";

// OverlayPanelKernel::shade, integer for integer.
constexpr const char* kPanelFragment = R"(
layout(binding = 0) uniform sampler2D u_panelSource;
int floorDiv(int a, int b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }
void main() {
    int zoom = max(u_zoom, 1);
    ivec2 p = ivec2(gl_FragCoord.xy);
    ivec2 q = ivec2(u_sourceX + floorDiv(p.x - u_targetX, zoom), u_sourceY + floorDiv(p.y - u_targetY, zoom));
    ivec2 size = textureSize(u_panelSource, 0);
    if (q.x < 0 || q.y < 0 || q.x >= size.x || q.y >= size.y) { finish(vec4(0.0, 0.0, 0.0, 1.0)); return; }
    finish(vec4(texelFetch(u_panelSource, q, 0).rgb, 1.0));
}
)";

}  // namespace

glm::mat4 pixelToClip(int width, int height) {
    // x: 0..width -> -1..1; y: 0..height (down) -> 1..-1 (the top row is clip +y, as a
    // camera's up is); z stays, w = 1.
    glm::mat4 m(1.0f);
    m[0][0] = 2.0f / float(width);
    m[1][1] = -2.0f / float(height);
    m[3][0] = -1.0f;
    m[3][1] = 1.0f;
    return m;
}

ProgramDesc overlayFillProgram() {
    ProgramDesc d = describeProgram<OverlayFillParams>("OverlayFill", VertexInput::Mesh, "hud::OverlayFillParams");
    d.gl.fragment = kFillFragment;
    d.gl.uniforms = {{"u_viewProj", UniformType::Mat4, offsetof(OverlayFillParams, viewProj)}};
    d.soft = engine::render::soft::makeKernel<OverlayFillKernel, OverlayFillParams>();
    return d;
}

ProgramDesc overlayPanelProgram() {
    ProgramDesc d =
        describeProgram<OverlayPanelParams>("OverlayPanel", VertexInput::Fullscreen, "hud::OverlayPanelParams");
    d.gl.fragment = kPanelFragment;
    d.gl.uniforms = {
        {"u_sourceX", UniformType::Int, offsetof(OverlayPanelParams, sourceX)},
        {"u_sourceY", UniformType::Int, offsetof(OverlayPanelParams, sourceY)},
        {"u_targetX", UniformType::Int, offsetof(OverlayPanelParams, targetX)},
        {"u_targetY", UniformType::Int, offsetof(OverlayPanelParams, targetY)},
        {"u_zoom", UniformType::Int, offsetof(OverlayPanelParams, zoom)},
    };
    d.gl.textures = {
        {"u_panelSource", offsetof(OverlayPanelParams, source), 0, TextureRead::Texel, TextureUse::Sampled}};
    d.check = [](const void* params, const DrawCheck& check) {
        const auto& p = *static_cast<const OverlayPanelParams*>(params);
        if (p.zoom < 1 || p.zoom > 64) check.fail("panel zoom " + std::to_string(p.zoom) + " is not in 1..64");
    };
    d.soft = engine::render::soft::makeKernel<OverlayPanelKernel, OverlayPanelParams>();
    return d;
}

}  // namespace hud
