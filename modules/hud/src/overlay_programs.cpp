// SPDX-License-Identifier: MIT
#include "hud/overlay_programs.hpp"

#include <string>

#include "engine/render/kernel/program_kernel.hpp"
#include "engine/render/shader_interface.hpp"
#include "hud_glsl.hpp"  // generated from glsl/
#include "overlay_kernels.hpp"

namespace hud {

using namespace engine::render;

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
    d.gl.fragment = glsl::kFillFragment;
    d.soft = engine::render::soft::makeKernel<OverlayFillKernel, OverlayFillParams>();
    return d;
}

ProgramDesc overlayPanelProgram() {
    ProgramDesc d =
        describeProgram<OverlayPanelParams>("OverlayPanel", VertexInput::Fullscreen, "hud::OverlayPanelParams");
    d.gl.fragment = samplerDeclarations(d.gl) + glsl::kPanelFragment;
    d.check = [](const void* params, const DrawCheck& check) {
        const auto& p = *static_cast<const OverlayPanelParams*>(params);
        if (p.zoom < 1 || p.zoom > 64) check.fail("panel zoom " + std::to_string(p.zoom) + " is not in 1..64");
    };
    d.soft = engine::render::soft::makeKernel<OverlayPanelKernel, OverlayPanelParams>();
    return d;
}

}  // namespace hud
