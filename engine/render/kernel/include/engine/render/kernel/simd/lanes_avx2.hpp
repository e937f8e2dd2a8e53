// SPDX-License-Identifier: MIT
#pragma once
// lanes_sse2.hpp's operations with eight lanes, compiled for AVX2 (avx2_target.hpp): include
// it only where the CPU's support is checked before any of it runs (SimdIsa::Avx2).
#include <cstdint>

#include <immintrin.h>

#include "engine/render/kernel/simd/avx2_target.hpp"

SOFT_AVX2_BEGIN
namespace engine::render::soft::simd::avx2 {

struct Mask {
    __m256 v;
    [[gnu::always_inline]] std::uint32_t bits() const { return std::uint32_t(_mm256_movemask_ps(v)); }
    [[gnu::always_inline]] bool any() const { return bits() != 0; }
    [[gnu::always_inline]] friend Mask operator&(Mask a, Mask b) { return {_mm256_and_ps(a.v, b.v)}; }
    [[gnu::always_inline]] friend Mask operator|(Mask a, Mask b) { return {_mm256_or_ps(a.v, b.v)}; }
    [[gnu::always_inline]] friend Mask andNot(Mask a, Mask b) { return {_mm256_andnot_ps(b.v, a.v)}; }
    [[gnu::always_inline]] static Mask fromBits(std::uint32_t bits) {
        const __m256i lane = _mm256_setr_epi32(1, 2, 4, 8, 16, 32, 64, 128);
        const __m256i b = _mm256_set1_epi32(int(bits));
        return {_mm256_castsi256_ps(_mm256_cmpeq_epi32(_mm256_and_si256(b, lane), lane))};
    }
};

struct Floats {
    static constexpr int kLanes = 8;
    __m256 v;
    [[gnu::always_inline]] static Floats splat(float x) { return {_mm256_set1_ps(x)}; }
    [[gnu::always_inline]] static Floats load(const float* p) { return {_mm256_loadu_ps(p)}; }
    [[gnu::always_inline]] static Floats laneIndex() {
        return {_mm256_setr_ps(0.0f, 1.0f, 2.0f, 3.0f, 4.0f, 5.0f, 6.0f, 7.0f)};
    }
    [[gnu::always_inline]] void store(float* p) const { _mm256_storeu_ps(p, v); }
    [[gnu::always_inline]] friend Floats operator+(Floats a, Floats b) { return {_mm256_add_ps(a.v, b.v)}; }
    [[gnu::always_inline]] friend Floats operator-(Floats a, Floats b) { return {_mm256_sub_ps(a.v, b.v)}; }
    [[gnu::always_inline]] friend Floats operator*(Floats a, Floats b) { return {_mm256_mul_ps(a.v, b.v)}; }
    [[gnu::always_inline]] friend Floats operator/(Floats a, Floats b) { return {_mm256_div_ps(a.v, b.v)}; }
    // Ordered, non-signalling: false for NaN, as the scalar comparisons.
    [[gnu::always_inline]] friend Mask operator<(Floats a, Floats b) { return {_mm256_cmp_ps(a.v, b.v, _CMP_LT_OQ)}; }
    [[gnu::always_inline]] friend Mask operator>(Floats a, Floats b) { return {_mm256_cmp_ps(a.v, b.v, _CMP_GT_OQ)}; }
    [[gnu::always_inline]] friend Mask operator>=(Floats a, Floats b) { return {_mm256_cmp_ps(a.v, b.v, _CMP_GE_OQ)}; }
};

[[gnu::always_inline]] inline Floats sqrt(Floats a) { return {_mm256_sqrt_ps(a.v)}; }
[[gnu::always_inline]] inline Floats maxOr(Floats a, Floats b) { return {_mm256_max_ps(a.v, b.v)}; }
[[gnu::always_inline]] inline Floats keepIf(Mask m, Floats a) { return {_mm256_and_ps(m.v, a.v)}; }

// One masked gather.
[[gnu::always_inline]] inline Floats gather(const float* texels, int width, Floats x, Floats y, Mask active) {
    const __m256i index = _mm256_add_epi32(_mm256_mullo_epi32(_mm256_cvttps_epi32(y.v), _mm256_set1_epi32(width)),
                                           _mm256_cvttps_epi32(x.v));
    return {_mm256_mask_i32gather_ps(_mm256_setzero_ps(), texels, index, active.v, 4)};
}

}  // namespace engine::render::soft::simd::avx2
SOFT_AVX2_END
