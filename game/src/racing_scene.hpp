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
#include "car_driver.hpp"
#include "engine/scene/mesh_library.hpp"
#include "forest.hpp"
#include "ground.hpp"
#include "track.hpp"

namespace racer {

struct Car {
    float distance = 60.0f;  // along the track, metres (starts past the grove at the start line)
    float speed = 28.0f;     // m/s
    // Where the car is and which way it faces, for the chase camera: on the autopilot the
    // track's point and tangent at `distance`; driven by the player, its own (car_driver.hpp).
    glm::vec3 position{0.0f};
    glm::vec3 forward{0.0f, 0.0f, 1.0f};
    bool driven = false;  // by the player: `motion` moves it, the autopilot waits
    CarMotion motion;
};

struct SceneOptions {
    std::filesystem::path contentDir;
    std::uint32_t seed = 1;
    ForestOptions forest{};
    // Every tree and bush gets its levels of detail (plant_levels.hpp); they are drawn once a
    // selection picks them (engine/scene/levels_of_detail.hpp).
    bool levelsOfDetail = false;
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

    // Advances the simulation by dt seconds: the autopilot drives the car along the track
    // at its speed, or the player's last controls drive it (takeWheel).
    void update(float dt);

    // The player drives from the next update on with these controls (taking over from the
    // autopilot where the car is, at its speed); called again each frame with that frame's.
    void takeWheel(const DriveControls& controls);
    // The autopilot drives again, from the track's point nearest the car, at its speed.
    void engageAutopilot();

private:
    engine::render::DirectionalLight sun_;
    engine::ecs::Registry registry_;
    engine::scene::MeshLibrary library_;
    Track track_;
    Ground ground_;
    engine::ecs::Entity car_;
    DriveControls controls_;
};

}  // namespace racer
