// SPDX-License-Identifier: MIT
#pragma once
// Where the racing scene's trees and bushes stand: Pure-style woodland along most of the lap
// ([Hathaway 2010] §3.1) — a tree line a couple of metres off the asphalt, big trees whose
// canopy reaches over the road, bushes on the verges, rows behind — broken by clearings that
// open onto the wooded hills of the distance; a grove across from the start line for the
// pre-race pan; the vista's trees on the far hills. A function of the seed, nothing else.
#include <vector>

#include "engine/core/ecs/registry.hpp"
#include "engine/scene/mesh_library.hpp"
#include "ground.hpp"
#include "track.hpp"

namespace racer {

struct ForestOptions {
    float treeSpacing = 5.0f;  // metres along the lap between tree-line trees, each side
    float bushSpacing = 3.5f;  // between verge bushes, each side
    int backRowTrees = 500;    // scattered 12 .. 45 m from the centre line in the woodland
    int groveTrees = 40;       // across from the start line, framed by the pan camera
    int vistaTrees = 600;      // on the hills beyond the track
};

// The woodland's stretches along the lap: false inside a clearing. `distance` wraps.
bool inWoodland(const Track& track, float distance);

// Places every plant as an entity. `trees` / `bushes`: the content's models in name order
// (tree_broadleaf, tree_palm, tree_tall; bush_fern, bush_round).
void plantForest(engine::ecs::Registry& registry, const Track& track, const Ground& ground,
                 const std::vector<engine::scene::ModelId>& trees, const std::vector<engine::scene::ModelId>& bushes,
                 Random& random, const ForestOptions& options);

}  // namespace racer
