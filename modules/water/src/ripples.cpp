// SPDX-License-Identifier: MIT
#include "water/ripples.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include "engine/core/error.hpp"
#include "engine/core/field_checks.hpp"

namespace water {

void validate(const Ripples& r) {
    const engine::FieldChecks check{"Ripples"};
    check.nonNegative(r.amplitude, "amplitude");
    check.nonNegative(r.wavelength, "wavelength");
    check.nonNegative(r.speed, "speed");
    if (!(r.wavelength > 0.0f)) throw engine::Error("Ripples.wavelength must be positive");
}

void rippleNormals(std::span<const engine::render::Vertex> rest, std::span<engine::render::Vertex> out,
                   const Ripples& r, float time) {
    constexpr float kTwoPi = 2.0f * std::numbers::pi_v<float>;
    const float k = kTwoPi / r.wavelength, w = kTwoPi * r.speed * time;
    for (std::size_t i = 0; i < rest.size(); ++i) {
        const glm::vec3 p = rest[i].position;
        // Slopes of two crossing waves; the normal of a height field h is (-dh/dx, 1, -dh/dz).
        const float sx =
            r.amplitude * std::cos(k * p.x + w) + 0.5f * r.amplitude * std::cos(0.7f * k * (p.x + p.z) - 1.3f * w);
        const float sz = r.amplitude * std::cos(k * p.z - 0.8f * w) +
                         0.5f * r.amplitude * std::cos(0.7f * k * (p.x + p.z) - 1.3f * w);
        glm::vec3 n = rest[i].normal;
        const float len = glm::length(n);
        n = len > 0.0f ? n / len : glm::vec3(0.0f, 1.0f, 0.0f);
        out[i] = rest[i];
        out[i].normal = glm::normalize(n + glm::vec3(-sx, 0.0f, -sz));
    }
}

}  // namespace water
