// SPDX-License-Identifier: MIT
#include "noise.hpp"

#include <cmath>

#include "prng.hpp"

namespace content {

namespace {

float lattice(int x, int y, int periodX, int periodY, std::uint32_t seed) {
    const int wx = ((x % periodX) + periodX) % periodX;
    const int wy = ((y % periodY) + periodY) % periodY;
    return static_cast<float>(hash3(wx, wy, seed) >> 8) * (1.0f / 16777216.0f);
}

float smooth(float t) { return t * t * (3.0f - 2.0f * t); }

}  // namespace

float valueNoise(float u, float v, int periodX, int periodY, std::uint32_t seed) {
    const float x = u * static_cast<float>(periodX);
    const float y = v * static_cast<float>(periodY);
    const float fx = std::floor(x);
    const float fy = std::floor(y);
    const int ix = static_cast<int>(fx);
    const int iy = static_cast<int>(fy);
    const float tx = smooth(x - fx);
    const float ty = smooth(y - fy);
    const float a = lattice(ix, iy, periodX, periodY, seed);
    const float b = lattice(ix + 1, iy, periodX, periodY, seed);
    const float c = lattice(ix, iy + 1, periodX, periodY, seed);
    const float d = lattice(ix + 1, iy + 1, periodX, periodY, seed);
    return (a + (b - a) * tx) + ((c + (d - c) * tx) - (a + (b - a) * tx)) * ty;
}

float fbm(float u, float v, int periodX, int periodY, int octaves, std::uint32_t seed) {
    float sum = 0.0f;
    float amplitude = 1.0f;
    float total = 0.0f;
    for (int o = 0; o < octaves; ++o) {
        sum += amplitude * valueNoise(u, v, periodX << o, periodY << o, seed + static_cast<std::uint32_t>(o) * 101u);
        total += amplitude;
        amplitude *= 0.5f;
    }
    return sum / total;
}

}  // namespace content
