// SPDX-License-Identifier: MIT
#pragma once
// The soft backend's kernel of SSAM's foliage depth program (foliage_depth_program.hpp): the
// colour pass's surface (MaskedLit's, its texture sampled through the backend's sample function:
// libssam links no soft-backend code), and the composite's mask at the fragment's pixel
// (CompositeKernel's compositeFactor: the same bits as the composite).
#include <limits>

#include <glm/glm.hpp>

#include "composite_kernel.hpp"
#include "engine/render/soft/kernel/fragment.hpp"
#include "engine/render/soft/kernel/programs.hpp"
#include "engine/render/soft/kernel/texture_lookup.hpp"
#include "foliage_depth_program.hpp"

namespace ssam {

struct FoliageDepthKernel {
    static constexpr engine::render::soft::ProgramNeeds kNeeds = engine::render::soft::MaskedLitProgram::kNeeds;
    static constexpr bool kReadsPixels = true;  // the mask is read at the fragment's pixel
    engine::render::soft::MaskedLitProgram surface;
    CompositeKernel composite;
    float threshold = 0.0f;
    engine::render::soft::TextureLookup::SampleFunction sample = nullptr;

    FoliageDepthKernel(const FoliageDepthParams& p, const engine::render::soft::TextureLookup& textures)
        : surface(engine::render::SurfaceParams{p.viewProj, p.baseColorFactor, p.baseColor, p.light}, textures),
          composite(CompositeParams{{}, p.mask, p.maskAdd, p.maskLerp, p.squareMask}, textures), threshold(p.threshold),
          sample(textures.sampleFunction()) {}

    glm::vec4 shade(const engine::render::soft::Fragment& f) const {
        // MaskedLit's shade(), spelled with its parts (shade() itself would link the sampler).
        const glm::vec4 c =
            surface.texture && sample
                ? surface.shadeSampled(f, sample(*surface.texture, surface.params.baseColor.sampler, f.uv, f.duv))
                : surface.light(f, surface.params.baseColorFactor * f.color);
        if (composite.compositeFactor(f.x, f.y) >= threshold) return c;
        return {glm::vec3(c), std::numeric_limits<float>::quiet_NaN()};  // fails every alpha test
    }
};

}  // namespace ssam
