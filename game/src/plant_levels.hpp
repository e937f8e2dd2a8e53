// SPDX-License-Identifier: MIT
#pragma once
// The plants' levels of detail from the committed content: each tree or bush file holds its
// levels as scenes (0 the full model, 1 the middle level, 2 the impostor) and
// content/lod/levels.json says below which height on screen each takes over (measured by the
// content generator, content/generator/lod_levels.hpp). Shared by the racing scene and
// ssam-bench's scenes.
#include <filesystem>
#include <map>

#include "engine/core/ecs/registry.hpp"
#include "engine/scene/levels_of_detail.hpp"
#include "engine/scene/mesh_library.hpp"

namespace racer {

// The crossfade band of the plants' level changes with levels of detail on (racer, ssam-bench):
// 10 % either side of each threshold, the hysteresis's band (engine::scene::LodView::crossfade).
inline constexpr float kLodCrossfade = 0.1f;

// Every level of `file` (a tree_* or bush_* model of `contentDir`/models) uploaded, level 0
// being `full` (the file's scene 0, already loaded). Throws engine::Error naming the file and
// the field when levels.json is missing, malformed or has no entry for the file.
engine::scene::LevelsOfDetail loadPlantLevels(engine::scene::MeshLibrary& library,
                                              const std::filesystem::path& contentDir,
                                              const std::filesystem::path& file, engine::scene::ModelId full);

// Gives every entity whose Renderable draws one of `levels`' full models those levels.
// Returns how many entities got them.
std::size_t attachPlantLevels(engine::ecs::Registry& registry,
                              const std::map<engine::scene::ModelId, engine::scene::LevelsOfDetail>& levels);

}  // namespace racer
