// SPDX-License-Identifier: MIT
#pragma once
// The soft backend's kernel of the tint program (tint_program.hpp): the same colour at
// every pixel, so it reads no interpolant and no texture.
#include <glm/glm.hpp>

#include "engine/render/kernel/fragment.hpp"
#include "engine/render/kernel/texture_lookup.hpp"
#include "tint/tint_program.hpp"

namespace tint {

struct TintKernel {
    static constexpr engine::render::soft::ProgramNeeds kNeeds{};
    glm::vec4 color;

    TintKernel(const TintParams& p, const engine::render::soft::TextureLookup&) : color(p.color, 1.0f) {}
    glm::vec4 shade(const engine::render::soft::Fragment&) const { return color; }
};

}  // namespace tint
