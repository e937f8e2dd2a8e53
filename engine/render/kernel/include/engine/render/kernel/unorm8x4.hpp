// SPDX-License-Identifier: MIT
#pragma once
// Four 8-bit UNORM values as floats, the values byteTables().unorm holds (i / 255.0f): an SSE2
// division is correctly rounded, as the table's was, so the bits are the same. For the kernels
// that decode a row of bytes at once (program-authoring header).
#if defined(__SSE2__) && !defined(SOFT_RASTER_SCALAR)  // as raster_support.hpp
#include <emmintrin.h>

namespace engine::render::soft {

// Lane i: (bytes[i] >> shift) & 0xFF over 255, for shift 0 (byte 0 of each 32-bit lane) to 24.
inline __m128 unorm8x4(__m128i lanes, int shift) {
    const __m128i bytes = _mm_and_si128(_mm_srl_epi32(lanes, _mm_cvtsi32_si128(shift)), _mm_set1_epi32(0xFF));
    return _mm_div_ps(_mm_cvtepi32_ps(bytes), _mm_set1_ps(255.0f));
}

}  // namespace engine::render::soft
#endif
