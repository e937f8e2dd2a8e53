// SPDX-License-Identifier: MIT
#pragma once
// The soft backend's kernels on the MaskedLit surface with the crossfade's dither
// (transparency/lod_dither.hpp): DitheredMaskedLit here, and the base HashedLit's and
// SharpenedCoverageLit's kernels share: the surface from the parameters' lit-surface members
// and the batch's LodDither.
#include <glm/glm.hpp>

#include "engine/render/kernel/fragment.hpp"
#include "engine/render/kernel/programs.hpp"
#include "engine/render/kernel/texture_lookup.hpp"
#include "transparency/lod_dither.hpp"

namespace transparency {

namespace soft = engine::render::soft;

struct DitheredSurfaceKernel {
    static constexpr soft::ProgramNeeds kNeeds = soft::MaskedLitProgram::kNeeds;  // uv and its derivatives included
    static_assert(kNeeds.uv && kNeeds.derivatives);
    static constexpr bool kReadsPixels = true;  // the dither depends on the pixel
    soft::MaskedLitProgram surface;
    LodDither dither = LodDither::Off;

    template <typename Params>
    DitheredSurfaceKernel(const Params& p, const soft::TextureLookup& textures)
        : surface(engine::render::SurfaceParams{p.viewProj, p.baseColorFactor, p.baseColor, p.light}, textures),
          dither(p.lodDither) {}
};

struct DitheredMaskedLitKernel : DitheredSurfaceKernel {
    DitheredMaskedLitKernel(const DitheredSurfaceParams& p, const soft::TextureLookup& textures)
        : DitheredSurfaceKernel(p, textures) {}

    glm::vec4 shade(const soft::Fragment& f) const {
        return lodDitherOutput(surface.shade(f), f.color.a, dither, f.x, f.y);
    }
};

}  // namespace transparency
