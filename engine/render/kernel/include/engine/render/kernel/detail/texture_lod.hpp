// SPDX-License-Identifier: MIT
#pragma once
// The level of detail of trilinear filtering, lambda = log2(rho) (OpenGL 4.6 §8.14.1, rho the
// larger of the two screen derivatives' lengths in texels), for the soft backend's samplers:
// the general one (sampler.cpp) one fragment at a time, the alpha sampler (alpha_sampler.hpp)
// four at a time. Both take it from here, with the same single-precision operations in the same
// order (the build has no FMA contraction), so every path gives the same bits on every x86-64
// machine and in every build.
//
// Why not the C library's log2f: glibc picks an FMA or a plain version by CPU, and its vector
// one (libmvec) another by CPU, so neither promises the same bits everywhere; and the per-lane
// calls were the one scalar step left in the samplers' SIMD path (soft_backend.md).
//
// The method: lambda = log2(rho^2) / 2, which needs no square root. rho^2 = 2^e * m with m in
// [sqrt(1/2), sqrt(2)), then log2 m = (2 / ln 2) * atanh s with s = (m - 1) / (m + 1),
// |s| <= 0.1716, as the odd series 2/ln2 * (s + s^3/3 + ... + s^9/9), evaluated as
// (c1 + c3 s^2) + s^4 (c5 + c7 s^2) + s^8 c9 (Estrin's scheme: short dependency chains). The
// first term left out, 2/ln2 * s^11/11, is below 1e-9; each step rounds once, so lambda is
// within about an ulp of the exact log2 (a GPU keeps 8 bits of its fraction), and exactly e / 2
// where m is 1.
#include <cstdint>
#include <cstring>

#if defined(__SSE2__) && !defined(SOFT_RASTER_SCALAR)
#include <emmintrin.h>
#define SOFT_TEXTURE_LOD_SSE2 1
#endif

namespace engine::render::soft {
namespace texture_lod {

// 2 / (k ln 2) for k = 1, 3, 5, 7, 9.
inline constexpr float kC1 = 2.88539008f, kC3 = 0.961796694f, kC5 = 0.577078016f, kC7 = 0.412198583f,
                       kC9 = 0.320598898f;
inline constexpr float kSqrt2 = 1.41421356f;

}  // namespace texture_lod

// lambda = log2(rho) from rhoSquared = rho^2 > 1, finite or +infinity (64 there, beyond any
// level). Other values: unspecified.
inline float textureLambda(float rhoSquared) {
    using namespace texture_lod;
    std::uint32_t bits;
    std::memcpy(&bits, &rhoSquared, sizeof bits);
    int exponent = static_cast<int>(bits >> 23) - 127;
    const std::uint32_t mantissaBits = (bits & 0x007FFFFFu) | 0x3F800000u;  // m in [1, 2)
    float m;
    std::memcpy(&m, &mantissaBits, sizeof m);
    if (m > kSqrt2) {  // into [sqrt(1/2), sqrt(2)): exact
        m *= 0.5f;
        exponent += 1;
    }
    const float s = (m - 1.0f) / (m + 1.0f);  // m - 1 exact (Sterbenz)
    const float s2 = s * s, s4 = s2 * s2, s8 = s4 * s4;
    const float p = ((kC1 + kC3 * s2) + s4 * (kC5 + kC7 * s2)) + s8 * kC9;
    return (s * p + static_cast<float>(exponent)) * 0.5f;
}

#if SOFT_TEXTURE_LOD_SSE2
// textureLambda of each lane, the same operations.
inline __m128 textureLambda4(__m128 rhoSquared) {
    using namespace texture_lod;
    const __m128i bits = _mm_castps_si128(rhoSquared);
    __m128i exponent = _mm_sub_epi32(_mm_srli_epi32(bits, 23), _mm_set1_epi32(127));
    __m128 m =
        _mm_castsi128_ps(_mm_or_si128(_mm_and_si128(bits, _mm_set1_epi32(0x007FFFFF)), _mm_set1_epi32(0x3F800000)));
    const __m128 above = _mm_cmpgt_ps(m, _mm_set1_ps(kSqrt2));
    m = _mm_or_ps(_mm_and_ps(above, _mm_mul_ps(m, _mm_set1_ps(0.5f))), _mm_andnot_ps(above, m));
    exponent = _mm_sub_epi32(exponent, _mm_castps_si128(above));  // the mask is -1: one more
    const __m128 one = _mm_set1_ps(1.0f);
    const __m128 s = _mm_div_ps(_mm_sub_ps(m, one), _mm_add_ps(m, one));
    const __m128 s2 = _mm_mul_ps(s, s), s4 = _mm_mul_ps(s2, s2), s8 = _mm_mul_ps(s4, s4);
    const __m128 low = _mm_add_ps(_mm_set1_ps(kC1), _mm_mul_ps(_mm_set1_ps(kC3), s2));
    const __m128 high = _mm_add_ps(_mm_set1_ps(kC5), _mm_mul_ps(_mm_set1_ps(kC7), s2));
    const __m128 p = _mm_add_ps(_mm_add_ps(low, _mm_mul_ps(s4, high)), _mm_mul_ps(s8, _mm_set1_ps(kC9)));
    return _mm_mul_ps(_mm_add_ps(_mm_mul_ps(s, p), _mm_cvtepi32_ps(exponent)), _mm_set1_ps(0.5f));
}
#endif

}  // namespace engine::render::soft
