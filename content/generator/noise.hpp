// SPDX-License-Identifier: MIT
#pragma once
// Tileable value noise and fractal sums of it, for procedural textures. Only +, * and
// floor are used, so results do not depend on the maths library.
#include <cstdint>

namespace content {

// Value noise with `period` lattice cells across [0, 1) in x and y (wraps at 1): smooth,
// in [0, 1].
float valueNoise(float u, float v, int periodX, int periodY, std::uint32_t seed);

// Sum of `octaves` value noises, each with twice the frequency and half the amplitude of the
// one before, normalised to [0, 1]. Tileable on [0, 1)^2.
float fbm(float u, float v, int periodX, int periodY, int octaves, std::uint32_t seed);

}  // namespace content
