// SPDX-License-Identifier: MIT
#pragma once
// The soft backend's kernel of DitheredMaskedLit (transparency/lod_dither.hpp): the MaskedLit
// surface, its crossfade weight divided out and the other level's pixels dropped.
#include <glm/glm.hpp>

#include "engine/render/kernel/fragment.hpp"
#include "engine/render/kernel/programs.hpp"
#include "engine/render/kernel/texture_lookup.hpp"
#include "transparency/lod_dither.hpp"

namespace transparency {

namespace soft = engine::render::soft;

struct DitheredMaskedLitKernel {
    static constexpr soft::ProgramNeeds kNeeds = soft::MaskedLitProgram::kNeeds;
    static constexpr bool kReadsPixels = true;  // the crossfade's screen-space dither (lod_dither.hpp)
    soft::MaskedLitProgram surface;
    LodDither dither = LodDither::Off;

    DitheredMaskedLitKernel(const DitheredSurfaceParams& p, const soft::TextureLookup& textures)
        : surface(engine::render::SurfaceParams{p.viewProj, p.baseColorFactor, p.baseColor, p.light}, textures),
          dither(p.dither) {}

    glm::vec4 shade(const soft::Fragment& f) const {
        return lodDitherOutput(surface.shade(f), f.color.a, dither, f.x, f.y);
    }
};

}  // namespace transparency
