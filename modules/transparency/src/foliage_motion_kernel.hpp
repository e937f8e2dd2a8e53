// SPDX-License-Identifier: MIT
#pragma once
// The soft backend's kernel of FoliageMotion (transparency/temporal.hpp): the surface's motion
// since the previous frame, from the normal slot of MaskedBatch::motionVertices, with the
// surface's alpha for the pipeline's alpha test. The GLSL in glsl/foliage_motion_fragment.glsl
// performs the same operations.
#include <glm/glm.hpp>

#include "engine/render/kernel/fragment.hpp"
#include "engine/render/kernel/programs.hpp"
#include "engine/render/kernel/texture_lookup.hpp"

namespace transparency {

namespace soft = engine::render::soft;

struct FoliageMotionKernel {
    // AlphaOnly's interpolants, and the normal (the motion).
    static constexpr soft::ProgramNeeds kNeeds{true, true, true, false, true};
    soft::AlphaOnlyProgram surface;

    FoliageMotionKernel(const engine::render::AlphaOnlyParams& p, const soft::TextureLookup& textures)
        : surface(p, textures) {}

    // The vertex stage interpolates the world-space motion as it does normals (mat3(model) * n,
    // perspective-correct), so a fragment carries the motion of its own point of the surface.
    glm::vec4 shade(const soft::Fragment& f) const { return {f.normal, surface.alpha(f)}; }
};

}  // namespace transparency
