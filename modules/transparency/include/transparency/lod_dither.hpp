// SPDX-License-Identifier: MIT
#pragma once
// The level-of-detail crossfade of the techniques that cannot fade by alpha. Inside a
// crossfade band both levels of a plant are drawn, each instance's weight in its tint alpha
// (engine/scene/levels_of_detail.hpp): SSAM and the blending techniques multiply alpha by it,
// but an alpha test, a hashed test or alpha to coverage would only thin the leaves. They keep
// a weight's share of the pixels instead, by a 4x4 ordered dither in screen space [Bayer 1973],
// as engines ship it (Unreal's dithered LOD transition): of the 16 thresholds of each 4x4
// block, one level keeps those below its weight and the other those at or above one minus its
// weight, so every pixel of the band is drawn by exactly one level (no hole, no double
// coverage) and the coarser level's share rises with its weight, in steps of 1/16. Each
// level's alpha is taken without the weight (divided out) before its test.
//
// Which pixels a level keeps goes by the parity of its level, since a crossfade always pairs
// two neighbouring levels: even levels keep thresholds below their weight, odd levels those at
// or above one minus theirs. Only batches of crossfading instances (DrawBatch::crossfading)
// are drawn dithered; a steady instance of weight 1 keeps every pixel either way.
//
// The weight is the interpolated vertex colour's alpha (the tint's alpha times the vertex
// alpha, which this content leaves at 1): under a dithered draw a vertex alpha below 1 is
// dithered too, the only way an alpha test can show it.
#include <array>
#include <cstdint>

#include <glm/glm.hpp>

#include "engine/render/param_block.hpp"
#include "engine/render/program.hpp"
#include "engine/render/program_desc.hpp"

namespace transparency {

enum class LodDither : std::uint8_t {
    Off = 0,        // not crossfading: the surface as it is
    KeepBelow = 1,  // an even level: keep where threshold < weight
    KeepAbove = 2,  // an odd level: keep where threshold >= 1 - weight
};

// The dither of a batch at `level` (DrawBatch::level), crossfading or not.
constexpr LodDither lodDitherFor(int level, bool crossfading) {
    if (!crossfading) return LodDither::Off;
    return level % 2 == 0 ? LodDither::KeepBelow : LodDither::KeepAbove;
}

// The 4x4 Bayer matrix's thresholds at pixel (x, y), (k + 0.5) / 16: exact in float, as in
// glsl/lod_dither.glsl.
inline float lodDitherThreshold(int x, int y) {
    static constexpr std::array<std::uint8_t, 16> kBayer4{0, 8, 2, 10, 12, 4, 14, 6, 3, 11, 1, 9, 15, 7, 13, 5};
    return (float(kBayer4[std::size_t((y & 3) * 4 + (x & 3))]) + 0.5f) / 16.0f;
}

inline bool lodDitherKeeps(LodDither dither, float weight, int x, int y) {
    if (dither == LodDither::Off) return true;
    const float threshold = lodDitherThreshold(x, y);
    return dither == LodDither::KeepBelow ? threshold < weight : threshold >= 1.0f - weight;
}

// The surface's colour with the weight divided out of its alpha (undithered: unchanged).
inline glm::vec4 lodFadeRemoved(const glm::vec4& c, float weight, LodDither dither) {
    return dither == LodDither::Off ? c : glm::vec4(glm::vec3(c), c.a / weight);
}

// The colour with alpha 0 (no coverage, below every alpha-test reference above 0) where the
// pixel belongs to the other level.
inline glm::vec4 lodDitherDropped(const glm::vec4& c, float weight, LodDither dither, int x, int y) {
    return lodDitherKeeps(dither, weight, x, y) ? c : glm::vec4(glm::vec3(c), 0.0f);
}

// Both: what a dithered surface outputs.
inline glm::vec4 lodDitherOutput(const glm::vec4& c, float weight, LodDither dither, int x, int y) {
    return lodDitherDropped(lodFadeRemoved(c, weight, dither), weight, dither, x, y);
}

// A program's draw check of its LodDither parameter (a value outside the enum is refused).
void checkLodDither(LodDither dither, const engine::render::DrawCheck& check);

// DitheredMaskedLit: the MaskedLit surface, dithered by `lodDither` (Off gives MaskedLit's
// output; techniques draw steady batches with MaskedLit itself).
#define TRANSPARENCY_DITHERED_SURFACE_PARAMS(UNIFORM, DIRECTION, TEXTURE) \
    UNIFORM(::transparency::LodDither, lodDither, ::transparency::LodDither::Off)
ENGINE_PARAM_BLOCK_ON_LIT_SURFACE(DitheredSurfaceParams, TRANSPARENCY_DITHERED_SURFACE_PARAMS);

engine::render::ProgramDesc ditheredMaskedLitProgram();

}  // namespace transparency
