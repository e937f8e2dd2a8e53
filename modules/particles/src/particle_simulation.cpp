// SPDX-License-Identifier: MIT
#include "particles/particle_simulation.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "engine/core/error.hpp"
#include "engine/core/field_checks.hpp"
#include "engine/scene/transform.hpp"

namespace particles {

void validate(const ParticleOptions& o) {
    const engine::FieldChecks check{"ParticleOptions"};
    if (o.maxParticles > kMaxParticles)
        throw engine::Error("ParticleOptions.maxParticles = " + std::to_string(o.maxParticles) +
                            " exceeds the limit of 1000000 particles");
    check.positive(o.lifetime, "lifetime");
    check.positive(o.startSize, "startSize");
    check.positive(o.endSize, "endSize");
    check.positive(o.softness, "softness");
    check.positive(o.thinning, "thinning");
    check.nonNegative(o.drag, "drag");
    check.finite(o.gravity, "gravity");
}

namespace {
void validateEmitter(const WheelEmitter& e) {
    if (!std::isfinite(e.rate) || e.rate < 0.0f || e.rate > 1e7f)
        throw engine::Error("WheelEmitter.rate = " + std::to_string(e.rate) + " must be finite and in [0, 1e7]");
    if (!(e.inherit >= 0.0f && e.inherit <= 1.0f)) throw engine::Error("WheelEmitter.inherit must be in [0, 1]");
    if (!(e.sprayFraction >= 0.0f && e.sprayFraction <= 1.0f))
        throw engine::Error("WheelEmitter.sprayFraction must be in [0, 1]");
    for (const glm::vec4& c : {e.dust, e.spray})
        for (int i = 0; i < 4; ++i)
            if (!std::isfinite(c[i])) throw engine::Error("WheelEmitter colour is not finite");
    for (const glm::vec3& w : e.wheels)
        for (int i = 0; i < 3; ++i)
            if (!std::isfinite(w[i])) throw engine::Error("WheelEmitter wheel position is not finite");
}
}  // namespace

ParticleSimulation::ParticleSimulation(const ParticleOptions& options, std::uint64_t seed)
    : state_(seed * 0x9E3779B97F4A7C15ull + 0x632BE59BD9B4E019ull) {
    setOptions(options);
}

void ParticleSimulation::setOptions(const ParticleOptions& options) {
    validate(options);
    options_ = options;
    if (particles_.size() > options_.maxParticles) particles_.resize(options_.maxParticles);
}

float ParticleSimulation::random() {
    state_ = state_ * 6364136223846793005ull + 1442695040888963407ull;
    return float(std::uint32_t(state_ >> 40)) * (1.0f / 16777216.0f);
}

float ParticleSimulation::sizeOf(const Particle& p) const {
    const float t = std::clamp(p.age / options_.lifetime, 0.0f, 1.0f);
    return options_.startSize + (options_.endSize - options_.startSize) * t;
}

float ParticleSimulation::opacityOf(const Particle& p) const {
    const float fadeOut = 1.0f - std::clamp(p.age / options_.lifetime, 0.0f, 1.0f);
    return fadeOut * std::exp(-std::max(p.travelled, 0.0f) / options_.thinning);
}

bool ParticleSimulation::emit(const Particle& p) {
    if (particles_.size() >= options_.maxParticles) {
        ++refused_;
        return false;
    }
    for (int i = 0; i < 3; ++i)
        if (!std::isfinite(p.position[i]) || !std::isfinite(p.velocity[i]))
            throw engine::Error("particle is not finite");
    particles_.push_back(p);
    return true;
}

void ParticleSimulation::update(engine::ecs::Registry& registry, float dt) {
    if (!std::isfinite(dt) || dt < 0.0f || dt > 10.0f)
        throw engine::Error("particles: dt " + std::to_string(dt) + " must be finite and in [0, 10] s");
    // Age and move; the dead are removed keeping the order (deterministic draw order).
    const float damping = std::exp(-options_.drag * dt);
    std::size_t kept = 0;
    for (Particle& p : particles_) {
        p.age += dt;
        if (p.age >= options_.lifetime) continue;
        p.velocity = p.velocity * damping - glm::vec3(0.0f, options_.gravity * dt, 0.0f);
        p.position += p.velocity * dt;
        p.travelled += glm::length(p.velocity) * dt;
        particles_[kept++] = p;
    }
    particles_.resize(kept);

    registry.view<const engine::scene::Transform, WheelEmitter>().each(
        [&](const engine::scene::Transform& t, WheelEmitter& e) {
            validateEmitter(e);
            const glm::mat4 m = t.matrix();
            glm::vec3 carVelocity(0.0f);
            if (e.hasLastPosition && dt > 0.0f) carVelocity = (t.position - e.lastPosition) / dt;
            for (int i = 0; i < 3; ++i)
                if (!std::isfinite(carVelocity[i])) carVelocity = glm::vec3(0.0f);
            e.lastPosition = t.position;
            e.hasLastPosition = true;
            carry_ += e.rate * dt;
            const int spawns = int(std::min(carry_, 1e6f));
            carry_ -= float(spawns);
            for (int i = 0; i < spawns; ++i) {
                const glm::vec3 wheel = glm::vec3(m * glm::vec4(e.wheels[i % 4], 1.0f));
                const bool spray = random() < e.sprayFraction;
                Particle p;
                // One draw per statement: C++ leaves the order of a call's arguments and of `+`'s
                // operands unspecified (GCC right to left, Clang left to right); this is the
                // order GCC gave the goldens.
                const float dz = random() - 0.5f, dx = random() - 0.5f;
                p.position = wheel + glm::vec3(dx, 0.0f, dz) * 0.4f;
                // Thrown up and back, spread out.
                const glm::vec3 back = glm::vec3(m * glm::vec4(0.0f, 0.0f, -1.0f, 0.0f));
                const float vz = (random() - 0.5f) * 2.0f, vy = 1.0f + 2.5f * random(), vx = (random() - 0.5f) * 2.0f;
                const float throwSpeed = 1.5f + 2.0f * random();
                p.velocity = carVelocity * e.inherit + back * throwSpeed + glm::vec3(vx, vy, vz);
                p.age = random() * dt;  // spread over the step
                p.additive = spray ? 1.0f : 0.0f;
                p.color = spray ? e.spray : e.dust;
                emit(p);
            }
        });
}

}  // namespace particles
