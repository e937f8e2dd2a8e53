// SPDX-License-Identifier: MIT
#pragma once
// The soft backend's kernel of SSAM's foliage depth program (foliage_depth_program.hpp): the
// colour pass's alpha (MaskedLit's, its texture sampled through the backend's sample function:
// libssam links no soft-backend code), and the composite's mask at the fragment's pixel
// (CompositeKernel's compositeFactor: the same bits as the composite).
#include <limits>

#include <glm/glm.hpp>

#include "composite_kernel.hpp"
#include "engine/core/error.hpp"
#include "engine/render/kernel/fragment.hpp"
#include "engine/render/kernel/programs.hpp"  // AlphaOnlyProgram::kNeeds
#include "engine/render/kernel/texture_lookup.hpp"
#include "foliage_depth_program.hpp"

namespace ssam {

struct FoliageDepthKernel {
    // The alpha's inputs only, as AlphaOnlyProgram's: uv and its derivatives, the vertex alpha.
    static constexpr engine::render::soft::ProgramNeeds kNeeds = engine::render::soft::AlphaOnlyProgram::kNeeds;
    static constexpr bool kReadsPixels = true;  // the mask is read at the fragment's pixel
    float factorAlpha = 1.0f;
    const engine::render::soft::SoftTexture* texture = nullptr;
    engine::render::SamplerState sampler;
    engine::render::soft::TextureLookup::SampleFunction sample = nullptr;
    CompositeKernel composite;
    float threshold = 0.0f;

    FoliageDepthKernel(const FoliageDepthParams& p, const engine::render::soft::TextureLookup& textures)
        : factorAlpha(p.baseColorFactor.a), texture(textures.texture(p.baseColor.texture)),
          sampler(p.baseColor.sampler), sample(textures.sampleFunction()),
          composite(CompositeParams{{}, p.mask, p.maskAdd, p.maskLerp, p.squareMask}, textures),
          threshold(p.threshold) {
        // A lookup without the backend's sampler (the soft backend's draws always have one) would
        // leave the texture's alpha out of the test: refused rather than drawn wrong.
        if (texture && !sample) throw engine::Error("ssam foliage depth: the texture lookup offers no sample function");
    }

    // Only the alpha matters (the pass has no colour target; the alpha test reads it): MaskedLit's
    // alpha, factor * vertex colour * texel, in shade()'s order, without its lighting.
    glm::vec4 shade(const engine::render::soft::Fragment& f) const {
        float alpha = factorAlpha * f.color.a;
        if (texture) alpha *= sample(*texture, sampler, f.uv, f.duv).a;
        if (!(composite.compositeFactor(f.x, f.y) >= threshold))
            alpha = std::numeric_limits<float>::quiet_NaN();  // fails every alpha test
        return {0.0f, 0.0f, 0.0f, alpha};
    }
};

}  // namespace ssam
