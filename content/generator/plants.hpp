// SPDX-License-Identifier: MIT
#pragma once
// The trees and bushes as recipes (trunk, crown lobes, frond rings), so one recipe builds each
// level of detail: the full model ([Hathaway 2010] §3.3: many intersecting cards around a
// trunk) and the middle level, the same crown from a third of the cards at √3 times their
// side (the crown's card area kept), moved in so the outline stays, and a trunk of fewer sides — the SpeedTree recipe of
// "fewer, larger cards" further out. The far level (impostor.hpp) is drawn from the full one.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "geometry.hpp"

namespace content {

struct TrunkShape {
    float y0, y1, radius0, radius1;
    int sides;
    float uRepeat;
};

struct FrondRing {
    glm::vec3 top;
    int count;
    float length, minElevation, maxElevation;
};

struct PlantRecipe {
    std::string name;  // the model's file stem: tree_broadleaf, bush_fern, ...
    std::uint32_t seed;
    bool fronds;  // the frond texture (palms, ferns) instead of the leaf cluster
    std::optional<TrunkShape> trunk;
    std::vector<Lobe> lobes;
    std::vector<FrondRing> rings;
};

// The five plants of the racing scene, in the order content.cpp writes them.
const std::vector<PlantRecipe>& plantRecipes();

struct PlantMeshes {
    std::optional<MeshData> trunk;  // opaque bark
    MeshData cards;                 // MASK foliage
};

// Level 0: the full model, card for card the committed one. Level 1: the middle level.
PlantMeshes buildPlant(const PlantRecipe& recipe, int level);

}  // namespace content
