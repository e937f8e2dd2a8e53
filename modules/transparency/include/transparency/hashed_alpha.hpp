// SPDX-License-Identifier: MIT
#pragma once
// Hashed alpha testing [Wyman & McGuire 2017]: a fragment is kept when its alpha reaches a
// threshold hashed from a stable coordinate at a scale of about one pixel, instead of a fixed
// reference. Coverage is then right on average, and the pattern sticks to the surface (no
// shimmer under a moving camera) because the hashed coordinate moves with it.
//
// This header is the CPU side of the threshold (the soft backend's kernel and the tests call
// it); the GLSL in src/hashed_program.cpp performs the same IEEE operations in the same order
// (`precise`), with an integer hash, so both backends agree bit for bit given the same
// coordinate and derivatives. What they are given differs slightly (README "hashed"):
// GL's derivatives are per-quad differences of the interpolated uv/w and 1/w, the soft
// backend's come from the triangle's planes.
//
// The stable coordinate is the texture coordinate, not the position: the wind module bends
// positions and leaves uv alone, and every instance of a mesh shares its object space, so a
// per-instance seed (seedOfInstance) tells instances apart.
#include <cmath>
#include <cstdint>

#include <glm/glm.hpp>

#include "engine/core/bit_cast.hpp"
#include "engine/render/program.hpp"
#include "engine/render/program_desc.hpp"
#include "engine/render/texture.hpp"
#include "transparency/lod_dither.hpp"

namespace transparency {

// PCG-style 3D integer hash (Jarzynski & Olano 2020, "Hash Functions for GPU Rendering",
// JCGT 9(3), pcg3d): integer multiplies, adds, shifts, the same in GLSL's uint arithmetic.
inline glm::uvec3 pcg3d(glm::uvec3 v) {
    v = v * 1664525u + 1013904223u;
    v.x += v.y * v.z;
    v.y += v.z * v.x;
    v.z += v.x * v.y;
    v ^= v >> 16u;
    v.x += v.y * v.z;
    v.y += v.z * v.x;
    v.z += v.x * v.y;
    return v;
}

// A uniform value in [0, 1): the top 24 bits of the hash, exact in a float.
inline float hashToUnit(std::uint32_t h) { return float(h >> 8u) * (1.0f / 16777216.0f); }

// The per-instance seed: the bits of the instance's translation, hashed. Stable across
// frames, camera moves and wind (the wind bends vertices, not the instance's transform).
inline std::uint32_t seedOfInstance(const glm::mat4& model) {
    const glm::uvec3 bits{engine::bitCast<std::uint32_t>(model[3].x), engine::bitCast<std::uint32_t>(model[3].y),
                          engine::bitCast<std::uint32_t>(model[3].z)};
    return pcg3d(bits).x;
}

namespace hashed_detail {

// log2(m) for m in [1, 2), as a cubic in (m - 1) (least-squares fit; within 0.005 of log2,
// exact 0 at m = 1 and 1 at m = 2, increasing): the blend factor between the two scales only
// needs to move smoothly from 0 to 1, and a polynomial of plain operations rounds alike on
// both backends where log2() does not.
inline float log2Mantissa(float m) {
    const float t = m - 1.0f;
    return ((0.15824871f * t - 0.57561607f) * t + 1.41736736f) * t;
}

// x = 2^e * m, m in [1, 2): the exponent e and log2Mantissa(m) (x positive, normal).
struct Log2Split {
    int exponent = 0;
    float fraction = 0.0f;  // in [0, 1)
};
inline Log2Split splitLog2(float x) {
    const std::uint32_t bits = engine::bitCast<std::uint32_t>(x);
    const int exponent = int((bits >> 23u) & 0xffu) - 127;
    const float mantissa = engine::bitCast<float>((bits & 0x007fffffu) | 0x3f800000u);
    return {exponent, log2Mantissa(mantissa)};
}

// The cell coordinate floor(scale * u), clamped so that it converts to an int anywhere.
inline std::uint32_t cellOf(float scaled) {
    const float f = std::floor(scaled);
    const float c = f > 1073741824.0f ? 1073741824.0f : (f < -1073741824.0f ? -1073741824.0f : f);
    return engine::bitCast<std::uint32_t>(std::int32_t(c));
}

// The hash of uv's cell at scale 2^level (per axis: levels.x, levels.y), seeded.
inline float cellHash(glm::vec2 uv, glm::ivec2 levels, std::uint32_t seed) {
    const float sx = std::ldexp(1.0f, levels.x), sy = std::ldexp(1.0f, levels.y);
    const glm::uvec3 key{cellOf(sx * uv.x), cellOf(sy * uv.y),
                         seed ^ (std::uint32_t(levels.x) * 0x9e3779b9u) ^ (std::uint32_t(levels.y) * 0x85ebca6bu)};
    return hashToUnit(pcg3d(key).x);
}

// The CDF correction [Wyman & McGuire 2017]: the sum of two uniform hashes weighted (1 - f, f)
// is not uniform; this maps it back onto [0, 1] uniformly, so the fraction of fragments kept
// equals alpha. a = min(f, 1 - f).
inline float uniformFromBlend(float x, float f) {
    const float a = f < 1.0f - f ? f : 1.0f - f;
    float t = x;
    if (x < 1.0f - a) {
        if (x < a) t = (x * x) / (2.0f * a * (1.0f - a));
        else t = (x - 0.5f * a) / (1.0f - a);
    } else {
        t = 1.0f - ((1.0f - x) * (1.0f - x)) / (2.0f * a * (1.0f - a));
    }
    // Clamped to (0, 1]: a threshold of 0 would keep alpha-0 fragments.
    return t > 1e-6f ? (t < 1.0f ? t : 1.0f) : 1e-6f;
}

}  // namespace hashed_detail

// The hashed threshold of a fragment at texture coordinate uv with screen derivatives dx, dy
// of uv, seeded. hashScale: the hash cell's size in pixels (1: about one pixel).
//  - isotropic: the scale from the larger derivative, max(|d uv/dx|, |d uv/dy|); the hashes at
//    the two powers of two around 1 / (hashScale * that) are blended by the fraction of its
//    log2, then CDF-corrected.
//  - anisotropic: a scale per uv axis from that axis' larger derivative (times sqrt 2, the
//    paper's 0.707 for two dimensions), floor and ceiling per axis, the blend factor from the
//    distances of the per-axis fractions to the two corners.
inline float hashedThreshold(glm::vec2 uv, glm::vec2 dx, glm::vec2 dy, std::uint32_t seed, float hashScale,
                             bool anisotropic) {
    using namespace hashed_detail;
    // log2(1 / D) = -(e + m) for D = 2^e * 2^m: floor -e - 1 and ceil -e when m > 0, else both -e;
    // the fraction is 1 - m. No division, no log2(): exact on both backends.
    auto levels = [](float d, int& floorLevel, int& ceilLevel, float& fraction) {
        if (!(d > 1.1754944e-38f)) d = 1.1754944e-38f;  // zero, denormal or NaN derivative: the finest
        if (!(d < 3.4e38f)) d = 3.4e38f;                // infinite: the coarsest
        const Log2Split s = splitLog2(d);
        // Limit the levels to what the cell coordinates can represent.
        const int e = s.exponent < -60 ? -60 : (s.exponent > 60 ? 60 : s.exponent);
        ceilLevel = -e;
        floorLevel = s.fraction > 0.0f ? -e - 1 : -e;
        fraction = s.fraction > 0.0f ? 1.0f - s.fraction : 0.0f;
    };
    float x = 0.0f, f = 0.0f;
    if (!anisotropic) {
        const float lx = std::sqrt(dx.x * dx.x + dx.y * dx.y), ly = std::sqrt(dy.x * dy.x + dy.y * dy.y);
        int lo = 0, hi = 0;
        levels(hashScale * (lx > ly ? lx : ly), lo, hi, f);
        const float h0 = cellHash(uv, {lo, lo}, seed), h1 = cellHash(uv, {hi, hi}, seed);
        x = (1.0f - f) * h0 + f * h1;
    } else {
        const float ax = std::fabs(dx.x) > std::fabs(dy.x) ? std::fabs(dx.x) : std::fabs(dy.x);
        const float ay = std::fabs(dx.y) > std::fabs(dy.y) ? std::fabs(dx.y) : std::fabs(dy.y);
        glm::ivec2 lo, hi;
        glm::vec2 fr;
        levels(hashScale * ax * 1.41421354f, lo.x, hi.x, fr.x);
        levels(hashScale * ay * 1.41421354f, lo.y, hi.y, fr.y);
        const float h0 = cellHash(uv, lo, seed), h1 = cellHash(uv, hi, seed);
        const float toLow = std::sqrt(fr.x * fr.x + fr.y * fr.y);
        const float toHigh = std::sqrt((1.0f - fr.x) * (1.0f - fr.x) + (1.0f - fr.y) * (1.0f - fr.y));
        f = toLow / (toLow + toHigh);
        x = (1.0f - f) * h0 + f * h1;
    }
    return uniformFromBlend(x, f);
}

// HashedLit: the MaskedLit surface (the same colour and alpha bits), then hashed alpha
// testing: the output alpha is 1 where alpha >= hashedThreshold(uv, ...), else 0, for a
// pipeline that discards below 0.5.
struct HashedLitParams {
    glm::mat4 viewProj{1.0f};
    glm::vec4 baseColorFactor{1.0f};
    engine::render::TextureBinding baseColor;
    engine::render::DirectionalLight light;
    std::uint32_t seed = 0;  // seedOfInstance, mixed with the frame's seed under TAA
    float hashScale = 1.0f;  // the hash cell, in pixels; > 0
    bool anisotropic = false;
    bool outputThreshold = false;          // tests: output (t, t, t, 1) instead of the surface
    LodDither lodDither = LodDither::Off;  // a crossfading instance's level (lod_dither.hpp)
};

engine::render::ProgramDesc hashedLitProgram();

}  // namespace transparency
