// SPDX-License-Identifier: MIT
#pragma once
// Animated water normals: two travelling waves tilt each vertex normal, so the sun's
// highlight moves over the surface. Geometry stays flat (pools are shallow and small).
#include <span>

#include "engine/render/vertex.hpp"

namespace water {

struct Ripples {
    float amplitude = 0.18f;  // tilt of the normal, radians-ish (slope of the waves)
    float wavelength = 1.7f;  // model-space units
    float speed = 0.6f;       // waves per second
};

// Throws engine::Error naming the field when a value is NaN, infinite or negative
// (wavelength must be positive).
void validate(const Ripples& ripples);

// `out` = `rest` with normals tilted by the waves at `time`; never NaN (a zero rest normal
// stays +Y).
void rippleNormals(std::span<const engine::render::Vertex> rest, std::span<engine::render::Vertex> out,
                   const Ripples& ripples, float time);

}  // namespace water
