// SPDX-License-Identifier: MIT
#include "wind/sway.hpp"

#include <cmath>
#include <numbers>

namespace wind {

using engine::render::Vertex;

namespace {
constexpr float kTwoPi = 2.0f * std::numbers::pi_v<float>;

glm::vec3 horizontal(const glm::vec3& d) { return glm::normalize(glm::vec3(d.x, 0.0f, d.z)); }
}  // namespace

glm::vec3 bendAtTop(const Wind& wind, const PlantPose& plant, float time) {
    const glm::vec3 along = horizontal(wind.direction);
    const glm::vec3 across(-along.z, 0.0f, along.x);
    const glm::vec3 foot(plant.model[3]);
    const float phase = plant.sway.phase;
    // A gust is a front moving downwind: its phase depends on how far downwind the plant is.
    const float gustPhase = kTwoPi * (wind.gustFrequency * time - glm::dot(foot, along) / wind.gustWavelength);
    const float g = 0.5f + 0.5f * std::sin(gustPhase);
    const float gust = wind.gustStrength * g * g;
    const float sway = 0.65f + 0.35f * std::sin(kTwoPi * wind.swayFrequency * time + phase);
    const float cross = 0.25f * std::sin(kTwoPi * wind.swayFrequency * 1.3f * time + 1.7f * phase);
    return wind.strength * plant.sway.flexibility * ((sway + gust) * along + cross * across);
}

engine::scene::Aabb deformVertices(std::span<const Vertex> rest, std::span<Vertex> out, std::span<glm::vec3> push,
                                   const Wind& wind, const PlantPose& plant, float time, bool flutter, float decay,
                                   std::span<const SphereCollider> colliders) {
    const glm::vec3 bend = bendAtTop(wind, plant, time) * plant.weight;
    const glm::mat3 normalToWorld(plant.model);
    const float flutterTime = kTwoPi * wind.flutterFrequency * time + plant.sway.phase;
    const float flutterAmplitude = flutter ? wind.flutterAmplitude * plant.sway.flexibility * plant.weight : 0.0f;
    const float inverseHeight = plant.height > 0.0f ? 1.0f / plant.height : 0.0f;
    engine::scene::Aabb bounds;
    for (std::size_t i = 0; i < rest.size(); ++i) {
        const Vertex& r = rest[i];
        // Stiff at the foot, flexible at the top: the classic quadratic bend.
        const float h = glm::clamp((r.position.y - plant.baseY) * inverseHeight, 0.0f, 1.0f);
        glm::vec3 p = glm::vec3(plant.model * glm::vec4(r.position, 1.0f)) + bend * (h * h);
        if (flutterAmplitude > 0.0f) {
            // Leaf-plane flutter: the card moves along its own normal, with a phase that
            // varies smoothly over the crown so neighbouring cards ripple, not jump.
            const glm::vec3 n = normalToWorld * r.normal;
            const float len = glm::length(n);
            if (len > 0.0f) {
                const float wave =
                    std::sin(flutterTime + 2.3f * r.position.x + 1.9f * r.position.z + 1.3f * r.position.y);
                p += n * (flutterAmplitude * h * wave / len);
            }
        }
        // Collision: the push of earlier frames springs back towards rest, then every
        // collider moves the vertex out of its sphere; what that took is remembered.
        glm::vec3 carried = push[i] * decay;
        glm::vec3 q = p + carried;
        for (const SphereCollider& c : colliders) {
            const float keep = c.radius + wind.colliderMargin;
            const glm::vec3 d = q - c.center;
            const float distance2 = glm::dot(d, d);
            if (!(distance2 < keep * keep)) continue;
            const float distance = std::sqrt(distance2);
            const glm::vec3 outward = distance > 1e-6f ? d / distance : glm::vec3(0.0f, 1.0f, 0.0f);
            const glm::vec3 target = c.center + outward * keep;
            carried += target - q;
            q = target;
        }
        push[i] = carried;
        Vertex v = r;
        v.position = glm::vec3(plant.inverseModel * glm::vec4(q, 1.0f));
        out[i] = v;
        bounds.add(v.position);
    }
    return bounds;
}

}  // namespace wind
