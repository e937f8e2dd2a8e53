// SPDX-License-Identifier: MIT
#pragma once
// The wind's parameters, a component on one entity of the registry (no Wind entity: no
// deformation), and the per-tree sway state. Units: metres, seconds, hertz.
#include <glm/glm.hpp>

namespace wind {

struct Wind {
    glm::vec3 direction{1.0f, 0.0f, 0.35f};  // world space, normalised on use; y is ignored
    float strength = 0.35f;                  // sway at the top of a fully flexible plant, metres
    float swayFrequency = 0.45f;             // Hz, the slow bend of the whole plant
    float gustStrength = 0.8f;               // a gust adds up to this fraction of `strength`
    float gustFrequency = 0.12f;             // Hz, how often gusts roll through
    float gustWavelength = 40.0f;            // metres: gusts travel with the wind, so trees downwind follow later
    float flutterAmplitude = 0.035f;         // metres, leaf cards moving along their plane normal
    float flutterFrequency = 2.6f;           // Hz
    float activeRadius = 45.0f;              // metres from the camera or a collider within which plants deform
    float springRate = 3.0f;                 // 1/s: how fast pushed foliage returns to rest (exponential)
    float colliderMargin = 0.05f;            // metres kept between a collider and any foliage vertex
};

// Throws engine::Error naming the field when a value is NaN, infinite or negative, or
// the direction has no horizontal component.
void validate(const Wind& wind);

// Per plant: how much it bends and where it is in the sway cycle. Added by
// WindSystem::attach() to every entity whose model has alpha-tested (foliage) parts.
struct Sway {
    float flexibility = 1.0f;  // 0 rigid .. 1 the full `strength`
    float phase = 0.0f;        // radians, per tree so neighbours do not move in lockstep
};

}  // namespace wind
