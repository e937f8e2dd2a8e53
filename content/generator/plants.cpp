// SPDX-License-Identifier: MIT
#include "plants.hpp"

#include <algorithm>
#include <cmath>

namespace content {

namespace {

// The middle level keeps one card in kCardRatio, each sqrt(kCardRatio) times as large.
constexpr int kCardRatio = 3;

}  // namespace

const std::vector<PlantRecipe>& plantRecipes() {
    static const std::vector<PlantRecipe> recipes = {
        {"tree_broadleaf",
         0x7EEB0AD1u,
         false,
         TrunkShape{0.0f, 3.6f, 0.22f, 0.12f, 9, 2.0f},
         {{{0.0f, 4.2f, 0.0f}, {2.0f, 1.6f, 2.0f}, 30, 1.6f, 2.4f},
          {{0.6f, 5.2f, -0.3f}, {1.3f, 1.1f, 1.3f}, 12, 1.4f, 2.0f}},
         {}},
        {"tree_tall",
         0x7A11u,
         false,
         TrunkShape{0.0f, 6.0f, 0.20f, 0.09f, 8, 2.0f},
         {{{0.0f, 3.6f, 0.0f}, {1.3f, 1.4f, 1.3f}, 16, 1.2f, 2.0f},
          {{0.0f, 5.2f, 0.0f}, {1.1f, 1.5f, 1.1f}, 16, 1.2f, 1.8f},
          {{0.0f, 6.8f, 0.0f}, {0.8f, 1.0f, 0.8f}, 12, 1.0f, 1.5f}},
         {}},
        {"tree_palm",
         0xBA1Bu,
         true,
         TrunkShape{0.0f, 4.8f, 0.18f, 0.12f, 8, 1.0f},
         {},
         {{{0.0f, 4.7f, 0.0f}, 14, 3.0f, -0.45f, 0.25f}, {{0.0f, 4.8f, 0.0f}, 10, 2.2f, 0.2f, 0.8f}}},
        {"bush_round", 0xB005Bu, false, std::nullopt, {{{0.0f, 1.0f, 0.0f}, {1.1f, 0.6f, 1.1f}, 28, 0.9f, 1.3f}}, {}},
        {"bush_fern",
         0xFE4Bu,
         true,
         std::nullopt,
         {},
         {{{0.0f, 0.2f, 0.0f}, 16, 1.4f, 0.4f, 0.9f}, {{0.0f, 0.2f, 0.0f}, 8, 1.1f, 0.9f, 1.3f}}},
    };
    return recipes;
}

PlantMeshes buildPlant(const PlantRecipe& recipe, int level) {
    const bool full = level == 0;
    // The middle level draws from a stream of its own: the full model's cards stay as committed.
    Pcg32 rng(full ? recipe.seed : recipe.seed ^ 0x10D1u);
    const float grow = full ? 1.0f : std::sqrt(float(kCardRatio));
    auto fewer = [&](int n) { return full ? n : std::max(3, (n + kCardRatio - 1) / kCardRatio); };
    PlantMeshes out;
    if (recipe.trunk) {
        const TrunkShape& t = *recipe.trunk;
        out.trunk = trunk(t.y0, t.y1, t.radius0, t.radius1, full ? t.sides : std::max(4, t.sides / 2), t.uRepeat);
    }
    for (Lobe lobe : recipe.lobes) {
        lobe.quads = fewer(lobe.quads);
        // Larger cards reach further out: their centres move in by the half size they gained,
        // so the crown's outline stays where the full model's is.
        const float gained = (grow - 1.0f) * 0.25f * (lobe.sizeMin + lobe.sizeMax);
        lobe.radii = glm::max(lobe.radii - glm::vec3(gained / 0.8f), 0.3f * lobe.radii);
        lobe.sizeMin *= grow;
        lobe.sizeMax *= grow;
        addCrownLobe(out.cards, rng, lobe);
    }
    // A frond is a card as long as the frond: fewer fronds, each as long and no wider (a
    // wider frond would change the texture's shape), so the middle fern keeps half of them.
    for (const FrondRing& ring : recipe.rings)
        addFronds(out.cards, rng, ring.top, full ? ring.count : std::max(3, ring.count / 2), ring.length,
                  ring.minElevation, ring.maxElevation);
    return out;
}

}  // namespace content
