// SPDX-License-Identifier: MIT
#pragma once
// A living-scene module as a program sees it: one row of the table that CMake generates from
// the one module list (ssam_module() lines, modules/CMakeLists.txt; the generator is
// modules/feature_table.cmake). A row names the module, the racer flag that flips it, whether
// it is on by default, and the function that makes its feature; the game reads all of that
// from the table, so adding a module edits no game file. The table is generated rather than
// filled by static self-registration because a static library drops an object file nothing
// refers to, and with it the registration.
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "engine/core/ecs/registry.hpp"
#include "engine/scene/frame_feature.hpp"
#include "engine/scene/mesh_library.hpp"

namespace engine::scene {

// A place on the ground where low plants may grow: its root on the ground, a turn about the
// vertical (radians) and a size factor. Where such places are is the scene's (the game's: its
// verges); the engine only hands them on.
struct GroundSpot {
    glm::vec3 root{0.0f};
    float yaw = 0.0f;
    float scale = 1.0f;
};

// What a module's factory may use: the scene its feature lives in.
struct FeatureContext {
    ecs::Registry& registry;
    const MeshLibrary& library;  // library.backend() is the backend its feature draws with
    std::uint32_t seed = 1;      // the scene's seed: placement and noise follow it
    // The spots where the scene lets low plants grow; unset when it has none (a glTF file). A
    // function, so that only a module that plants there pays for computing them.
    std::function<std::vector<GroundSpot>()> plantingSpots;
};

// Makes the module's feature; returns null when the scene offers it nothing to do (grass
// with no planting spots). Throws engine::Error, having released what it made, when the backend fails.
using FeatureFactory = std::unique_ptr<Feature> (*)(const FeatureContext&);

struct FeatureModule {
    const char* name;       // "wind": also its folder, its library ssam_<name> and SSAM_MODULE_<NAME>
    const char* flag;       // the racer flag that flips enabledByDefault ("--no-wind")
    const char* help;       // that flag's --help text
    bool enabledByDefault;  // on unless its flag is given
    FeatureFactory make;    // null: registered but left out of this build (-DSSAM_MODULE_<NAME>=OFF)
};

}  // namespace engine::scene
