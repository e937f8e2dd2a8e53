// SPDX-License-Identifier: MIT
#pragma once
// Half-float (binary16) conversion of four lanes at a time in SSE2, for the rasterizer's
// paths onto half-float targets (one_one_half_blend.hpp; e.g. the float coverage masks of
// [Hathaway 2010] §3.5.2), with exactly the bits of pixel_codec.hpp's encodeHalf and decodeHalf. The build
// targets plain x86-64 SSE2, so Imath converts without F16C: float -> half is
// imath_float_to_half's integer rounding to nearest even, half -> float its 65536-entry
// table. encodeHalf4 does the same integer steps per lane, except for results that are
// half denormals, where one float addition does the rounding (see there); decodeHalf4 reads
// the same table. Both are checked against the scalar codec for every half and for
// every float (tests/unit/soft/half_float4_test.cpp).
#include <cstdint>

#if defined(__SSE2__) && !defined(SOFT_RASTER_SCALAR)
#include <emmintrin.h>
#define SOFT_HALF_FLOAT4_SSE2 1
#endif

#include "engine/render/pixel_codec.hpp"

namespace engine::render::soft {

#if SOFT_HALF_FLOAT4_SSE2
// encodeHalf of each lane, in the low 16 bits of each 32-bit lane (the high bits are 0).
// Per lane, with ui = |v|'s bits and the sign put back at the end (imath_float_to_half):
//   NaN          0x7C00 | m | (m == 0), m = the top 10 mantissa bits (stays a NaN)
//   Inf, or ui > 0x477FEFFF (rounds past 65504)   0x7C00
//   ui >= 0x38800000 (a normal half)   (ui - 0x38000000 + 0xFFF + odd) >> 13, odd = bit 13:
//                                      round to nearest, ties to the even result
//   below        round(|v| / 2^-24) to nearest even, as a denormal (or 0, or the least
//                normal, 0x400, when it rounds up to it). Imath shifts the mantissa; here
//                |v| + 0.5f does it: the sum lies in [0.5, 1), where a float step is 2^-24,
//                so the addition (IEEE, round to nearest even) leaves 0.5 + k * 2^-24 with k
//                the rounded value: the sum's bits minus 0.5's are k. |v| <= 2^-25 (zero,
//                float denormals, the tie at 2^-25) gives k = 0, Imath's flush to zero.
inline __m128i encodeHalf4(__m128 v) {
    const __m128i bits = _mm_castps_si128(v);
    const __m128i sign = _mm_and_si128(_mm_srli_epi32(bits, 16), _mm_set1_epi32(0x8000));
    const __m128i ui = _mm_and_si128(bits, _mm_set1_epi32(0x7FFFFFFF));

    const __m128i rebiased = _mm_sub_epi32(ui, _mm_set1_epi32(0x38000000));
    const __m128i odd = _mm_and_si128(_mm_srli_epi32(rebiased, 13), _mm_set1_epi32(1));
    const __m128i normal = _mm_srli_epi32(_mm_add_epi32(_mm_add_epi32(rebiased, _mm_set1_epi32(0xFFF)), odd), 13);

    const __m128 sum = _mm_add_ps(_mm_castsi128_ps(ui), _mm_set1_ps(0.5f));
    const __m128i denormal = _mm_sub_epi32(_mm_castps_si128(sum), _mm_set1_epi32(0x3F000000));

    const __m128i m = _mm_srli_epi32(_mm_and_si128(ui, _mm_set1_epi32(0x7FFFFF)), 13);
    const __m128i nan = _mm_or_si128(_mm_or_si128(m, _mm_set1_epi32(0x7C00)),
                                     _mm_and_si128(_mm_cmpeq_epi32(m, _mm_setzero_si128()), _mm_set1_epi32(1)));

    // ui <= 0x7FFFFFFF, so the signed compares order it as unsigned.
    const __m128i isNormal = _mm_cmpgt_epi32(ui, _mm_set1_epi32(0x387FFFFF));
    const __m128i isInfinite = _mm_cmpgt_epi32(ui, _mm_set1_epi32(0x477FEFFF));
    const __m128i isNan = _mm_cmpgt_epi32(ui, _mm_set1_epi32(0x7F800000));
    auto select = [](__m128i use, __m128i a, __m128i b) {
        return _mm_or_si128(_mm_and_si128(use, a), _mm_andnot_si128(use, b));
    };
    __m128i h = select(isNormal, normal, denormal);
    h = select(isInfinite, _mm_set1_epi32(0x7C00), h);
    h = select(isNan, nan, h);
    return _mm_or_si128(h, sign);
}

// The four 16-bit values of encodeHalf4's lanes, packed into the low 64 bits (lane i in bits
// 16i..16i+15): sign-extending each first makes the saturating pack exact.
inline __m128i packHalf4(__m128i h) {
    const __m128i extended = _mm_srai_epi32(_mm_slli_epi32(h, 16), 16);
    return _mm_packs_epi32(extended, extended);
}

// decodeHalf of four halves.
inline __m128 decodeHalf4(std::uint16_t h0, std::uint16_t h1, std::uint16_t h2, std::uint16_t h3) {
    return _mm_setr_ps(decodeHalf(h0), decodeHalf(h1), decodeHalf(h2), decodeHalf(h3));
}
// decodeHalf of the four halves in the low 64 bits of `packed` (as packHalf4 lays them out).
inline __m128 decodeHalf4(__m128i packed) {
    return decodeHalf4(std::uint16_t(_mm_extract_epi16(packed, 0)), std::uint16_t(_mm_extract_epi16(packed, 1)),
                       std::uint16_t(_mm_extract_epi16(packed, 2)), std::uint16_t(_mm_extract_epi16(packed, 3)));
}
#endif

}  // namespace engine::render::soft
