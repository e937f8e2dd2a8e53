// SPDX-License-Identifier: MIT
#pragma once
// Every knob of the paper ([Hathaway 2010]), with Pure's values as defaults where the paper
// gives them.
#include <cstdint>

#include <glm/glm.hpp>

#include "engine/render/compare_func.hpp"

namespace ssam {

// Storage of rt_mask (§3.5.2). RGBA8 is Pure's: the ADD mask saturates at 1 after 255/alpha
// layers of one alpha. RGBA16F keeps both masks in one target unclamped. RG16F stores
// MAX and ADD in two single-channel R16F targets: a single RG target has only one blend
// equation for both channels, so the separate RGB = MAX / A = ADD blend of Table 3.1 needs
// either an alpha channel or two targets; two R16F targets are the same memory as one RG16F.
enum class MaskPrecision : std::uint8_t { RGBA8, RGBA16F, RG16F };

const char* maskPrecisionName(MaskPrecision precision);

struct Config {
    // mask = lerp(MAX mask, ADD mask, maskLerp): 0.85 = 85% additive, 15% max (§3.5.4, Listing 3.2).
    float maskLerp = 0.85f;
    // Colour-pass alpha reference (§3.5.3): Pure shipped ~64 of 255, between 64 and 128.
    float colorAlphaReference = 64.0f / 255.0f;
    // Colour-pass clear colour (§3.6.1, the clear-screen colour fix): shows through where the
    // mask is non-zero but the alpha-tested colour pass wrote nothing. A mid foliage green.
    glm::vec4 foliageClearColor{0.16f, 0.22f, 0.08f, 0.0f};
    // Square the final mask (§3.6.2, the squared alpha trick).
    bool squareMask = true;
    MaskPrecision maskPrecision = MaskPrecision::RGBA8;
    // The scene's depth function: Less for conventional depth, Greater for reverse-Z.
    engine::render::CompareFunc depthFunc = engine::render::CompareFunc::Less;

    // Throws engine::Error naming the knob when a value is out of range or not finite.
    void validate() const;
};

}  // namespace ssam
