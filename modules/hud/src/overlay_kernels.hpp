// SPDX-License-Identifier: MIT
#pragma once
// The soft backend's kernels of the HUD's programs (hud/overlay_programs.hpp).
#include <glm/glm.hpp>

#include "engine/render/kernel/fragment.hpp"
#include "engine/render/kernel/sampler.hpp"
#include "engine/render/kernel/texture_lookup.hpp"
#include "hud/overlay_programs.hpp"

namespace hud {

struct OverlayFillKernel {
    static constexpr engine::render::soft::ProgramNeeds kNeeds{false, false, false, true};
    static constexpr bool kReadsPixels = false;
    OverlayFillParams params;

    OverlayFillKernel(const OverlayFillParams& p, const engine::render::soft::TextureLookup&) : params(p) {}
    glm::vec4 shade(const engine::render::soft::Fragment& f) const { return f.color; }
};

struct OverlayPanelKernel {
    static constexpr engine::render::soft::ProgramNeeds kNeeds{};
    static constexpr bool kReadsPixels = true;
    OverlayPanelParams params;
    const engine::render::soft::SoftTexture* source = nullptr;

    OverlayPanelKernel(const OverlayPanelParams& p, const engine::render::soft::TextureLookup& textures)
        : params(p), source(textures.texture(p.source)) {}

    // floor((pixel - target) / zoom) as the GLSL computes it (integer division rounds
    // towards zero, so negative offsets are floored by hand).
    static int floorDiv(int a, int b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }

    glm::vec4 shade(const engine::render::soft::Fragment& f) const {
        const int zoom = params.zoom < 1 ? 1 : params.zoom;
        const int x = params.sourceX + floorDiv(f.x - params.targetX, zoom);
        const int y = params.sourceY + floorDiv(f.y - params.targetY, zoom);
        if (x < 0 || y < 0 || x >= source->desc.width || y >= source->desc.height) return {0.0f, 0.0f, 0.0f, 1.0f};
        return {glm::vec3(engine::render::soft::fetchTexel(*source, x, y)), 1.0f};
    }
};

}  // namespace hud
