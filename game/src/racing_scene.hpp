// SPDX-License-Identifier: MIT
#pragma once
// The racing scene on the ECS: the ground, road and shoulders built in code from the track
// (ground.hpp), models from content/ (trees, bushes, the car, water pools) placed with a
// seeded PRNG (forest.hpp), and the car driving laps. Everything is a function of the seed and
// the simulated time.
#include <filesystem>
#include <memory>
#include <vector>

#include "engine/core/ecs/registry.hpp"
#include "engine/scene/mesh_library.hpp"
#include "forest.hpp"
#include "ground.hpp"
#include "track.hpp"

namespace racer {

struct Car {
    float distance = 60.0f;  // along the track, metres (starts past the grove at the start line)
    float speed = 28.0f;    // m/s
};

struct SceneOptions {
    std::filesystem::path contentDir;
    std::uint32_t seed = 1;
    ForestOptions forest{};
};

class RacingScene {
public:
    RacingScene(engine::render::Backend& backend, const SceneOptions& options);

    engine::ecs::Registry& registry() { return registry_; }
    engine::scene::MeshLibrary& library() { return library_; }
    const Track& track() const { return track_; }
    const Ground& ground() const { return ground_; }
    engine::ecs::Entity car() const { return car_; }
    // A low late-afternoon sun behind the start-line grove as the pre-race pan sees it, so
    // its leaves are backlit and the light shafts fall through them towards the camera.
    const engine::render::DirectionalLight& sun() const { return sun_; }

    // Advances the simulation by dt seconds (the car drives along the track).
    void update(float dt);

private:
    engine::render::DirectionalLight sun_;
    engine::ecs::Registry registry_;
    engine::scene::MeshLibrary library_;
    Track track_;
    Ground ground_;
    engine::ecs::Entity car_;
};

}  // namespace racer
