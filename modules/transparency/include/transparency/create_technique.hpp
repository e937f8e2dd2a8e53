// SPDX-License-Identifier: MIT
#pragma once
// Making a technique, and every technique's options. SSAM's knobs are among them (the SSAM
// and SSAM+ adapters are the part of this module that uses ssam/), so this header, not
// technique.hpp, is where the transparency module meets ssam/: code that only draws through
// a Technique never includes ssam/.
#include <cstddef>
#include <memory>
#include <optional>

#include "engine/render/compare_func.hpp"
#include "ssam/core/settings.hpp"
#include "transparency/programs.hpp"
#include "transparency/technique.hpp"
#include "transparency/temporal.hpp"

namespace transparency {

// SSAM+ (README "SSAM+"): SSAM's mask and colour passes, with a float mask and the
// composite's coverage estimated from the MAX and ADD masks (transparency/programs.hpp
// CoverageModel) instead of lerp(max, add, 0.85) squared.
struct SsamPlusOptions {
    CoverageModel coverage = CoverageModel::EqualLayers;
    ssam::MaskPrecision maskPrecision = ssam::MaskPrecision::Rg16f;  // ADD must not saturate at 1
    // The colour pass's ([Hathaway 2010] §3.5.3; Pure's lay between 64 and 128 of 255). 128: with
    // the front layers and the composite's alpha-weighted average, within 1% of the lowest worst
    // ꟻLIP ratio to alpha testing's over tree, forest and vista at 1280x720 (136's), inside
    // Pure's range (ssam/docs/ssam_plus.md, "The colour reference").
    float colorAlphaReference = 128.0f / 255.0f;
    // The composite averages the foliage colour over 3x3 (programs.hpp CoverageBlurComposite):
    // lower error on every bench scene (ssam/docs/ssam_plus.md).
    bool compositeBlur = true;
    // A third geometry pass adds up the colours of the layers in front of the colour pass's leaf,
    // and the composite mixes their mean in by that leaf's alpha (programs.hpp
    // CoverageCompositeParams::frontLayers): lower error on every bench scene, still and in
    // motion (ssam/docs/ssam_plus.md, "The front layers").
    bool frontLayers = true;
};

// Hashed alpha testing (transparency/hashed_alpha.hpp).
struct HashedOptions {
    float hashScale = 1.0f;    // the hash cell in pixels, (0, 1e6): [Wyman & McGuire 2017]'s g_HashScale
    bool anisotropic = false;  // a scale per uv axis (the paper's anisotropic variant)
};

struct TechniqueOptions {
    // The scene's depth function, for every technique (SSAM's and SSAM+'s depthTest follow it).
    engine::render::CompareFunc depthFunc = engine::render::CompareFunc::Less;
    ssam::Settings ssam;  // SSAM's knobs (its depthTest is depthFunc's)
    // alpha-test's reference: unset, each material's own (FoliageDraw::alphaCutoff, glTF's
    // alphaCutoff, 0.5 by default); set, one reference for every draw.
    std::optional<float> alphaTestReference;
    std::size_t referenceFragmentsPerPixel = 256;  // the exact reference's cap (reported, never truncated silently)
    // WBOIT's weight (McGuire & Bavoil 2013 eq. 7) is tuned for view depths in metres,
    // 0.1 to 500: view depth * wboitDepthScale is what it sees.
    float wboitDepthScale = 1.0f;
    SsamPlusOptions ssamPlus;
    HashedOptions hashed;
    TemporalOptions temporal;  // the +taa techniques' temporal pass
};

// SSAM's settings for `options`: options.ssam with the scene's depth function; engine::Error when
// that function cannot order surfaces (Always, Never, Equal, NotEqual).
ssam::Settings ssamSettings(const TechniqueOptions& options);

// Throws engine::Error when the backend cannot run the technique (the message says why).
std::unique_ptr<Technique> createTechnique(TechniqueKind kind, engine::render::Backend& backend,
                                           const TechniqueOptions& options);

}  // namespace transparency
