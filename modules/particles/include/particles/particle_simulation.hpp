// SPDX-License-Identifier: MIT
#pragma once
// The particles themselves: spawned at the wheels of every entity with a WheelEmitter,
// moved by velocity, drag and gravity, aged and removed — a plain array, not ECS entities
// (a million particles would swamp the registry). Deterministic: a seeded PRNG, fixed order.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "engine/core/ecs/registry.hpp"

namespace particles {

inline constexpr std::size_t kMaxParticles = 1'000'000;

struct ParticleOptions {
    std::size_t maxParticles = 20000;  // 0 .. kMaxParticles; spawning stops at the cap
    float lifetime = 1.6f;             // seconds
    float startSize = 0.35f;           // metres (quad half-size), > 0
    float endSize = 1.4f;              // metres, > 0
    float drag = 1.2f;                 // 1/s
    float gravity = 1.5f;              // m/s^2 (dust settles slowly)
    float softness = 0.6f;             // metres of soft fade into the scene behind, > 0
    // Metres a particle travels from the wheel over which its opacity falls to 1/e, > 0: the
    // dust is thick at the wheels and thins along its trail, so a camera behind sees the car
    // through it rather than a wall of dust.
    float thinning = 2.5f;
    bool halfResolution = true;  // the layer at half size, upsampled by depth
};

// Throws engine::Error naming the field: NaN/inf, sizes <= 0, maxParticles over the cap.
void validate(const ParticleOptions& options);

// On the car: where its wheels are (model space) and how much they throw up.
struct WheelEmitter {
    glm::vec3 wheels[4] = {{-0.8f, 0.1f, 1.3f}, {0.8f, 0.1f, 1.3f}, {-0.8f, 0.1f, -1.3f}, {0.8f, 0.1f, -1.3f}};
    float rate = 400.0f;                         // particles per second, all wheels together (>= 0)
    float sprayFraction = 0.25f;                 // of them additive spray, the rest alpha-blended dust
    glm::vec4 dust{0.55f, 0.45f, 0.33f, 0.55f};  // straight colour and alpha
    glm::vec4 spray{0.9f, 0.95f, 1.0f, 0.35f};
    float inherit = 0.6f;  // fraction of the car's velocity the dust keeps (its wake)
    // Kept by the simulation: where the emitter was last step, for its velocity.
    glm::vec3 lastPosition{0.0f};
    bool hasLastPosition = false;
};

struct Particle {
    glm::vec3 position{0.0f};
    glm::vec3 velocity{0.0f};
    float age = 0.0f;
    float additive = 0.0f;  // 0 dust (alpha-blended), 1 spray (additive)
    glm::vec4 color{1.0f};
    float travelled = 0.0f;  // metres moved since it was spawned (update() adds each step's path)
};

class ParticleSimulation {
public:
    explicit ParticleSimulation(const ParticleOptions& options = {}, std::uint64_t seed = 1);

    const ParticleOptions& options() const { return options_; }
    void setOptions(const ParticleOptions& options);  // validated; drops particles over a lower cap

    // One step: ages and moves what lives, removes the dead, spawns at every WheelEmitter
    // (with a Transform) in proportion to dt, up to the cap. Throws for a bad dt or emitter.
    void update(engine::ecs::Registry& registry, float dt);
    // Adds one particle directly (tests, effects); false when at the cap.
    bool emit(const Particle& particle);

    const std::vector<Particle>& particles() const { return particles_; }
    float sizeOf(const Particle& p) const;
    // What its colour's alpha is multiplied by: 1 at birth, fading linearly to 0 over the
    // lifetime and by exp(-travelled / thinning) along its path from the wheel.
    float opacityOf(const Particle& p) const;
    // How many spawns the cap refused since construction.
    std::size_t refused() const { return refused_; }

private:
    float random();  // [0, 1)

    ParticleOptions options_;
    std::uint64_t state_;
    std::vector<Particle> particles_;
    float carry_ = 0.0f;  // fractional spawns carried to the next step
    std::size_t refused_ = 0;
};

}  // namespace particles
