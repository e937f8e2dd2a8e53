// SPDX-License-Identifier: MIT
#pragma once
// A plant's levels of detail and where each takes over, chosen by measured screen-space error.
//
// Level 0 is the full model, level 1 the middle one (plants.hpp: fewer, larger cards), level 2
// the impostor: two crossed vertical cards, each textured with the full model drawn
// orthographically from its side (ortho_render.hpp; the engine gives the texture coverage-
// preserving mips [Castaño 2010] when it uploads it, as for every MASK texture). SpeedTree's
// billboards, without the octahedral atlas [Brucks 2018]: two views suffice for plants that
// look alike from every side.
//
// The measurement, by screen-space error ([Luebke et al. 2002] §4.2: a level's deviation in
// object space, projected, bounds the pixels it can be off by): the full model and the level are
// drawn kDeviationPixels tall, alpha-tested, from kMeasuredYaws directions; where one covers a
// pixel the other does not, that pixel is as far off as the other's nearest covered pixel. The
// level's deviation is the kDeviationPercentile-th percentile of those distances over every
// pixel either covers (a covered pixel both share is 0 off), in metres, the worst direction's.
// Seen `h` pixels tall, a plant of height H metres is off by deviation * h / H pixels: a level
// is used while that is at most kLodPixelError, i.e. below kLodPixelError * H / deviation pixels
// of height. The per-plant figures are in content/lod/levels.json.
#include <cstdint>
#include <vector>

#include <nlohmann/json.hpp>

#include "engine/assets/image.hpp"
#include "plants.hpp"

namespace content {

inline constexpr float kLodPixelError = 0.5f;  // the bound: pixels a level may be off by on screen
inline constexpr int kDeviationPixels = 512;
inline constexpr double kDeviationPercentile = 90.0;
inline constexpr int kMeasuredYaws = 4;  // 0, 22.5, 45 and 67.5 degrees

struct PlantTextures {
    const engine::assets::RgbaImage* foliage;  // leaf cluster or frond
    const engine::assets::RgbaImage* bark;
};

struct PlantModel {
    std::vector<std::uint8_t> glb;  // scene 0: the full model; scene 1 the middle level; scene 2 the impostor
    // {"file", "height", "levels": [{"scene", "deviationMetres", "belowPixels"}, ...]}
    nlohmann::ordered_json lod;
};

// draco: the plant's meshes KHR_draco_mesh_compression-encoded (the committed content), or plain
// (the web page's content: its WebAssembly build has no Draco decoder).
PlantModel plantModel(const PlantRecipe& recipe, const PlantTextures& textures,
                      const std::vector<std::uint8_t>& foliagePng, const std::vector<std::uint8_t>& barkPng,
                      bool draco = true);

}  // namespace content
