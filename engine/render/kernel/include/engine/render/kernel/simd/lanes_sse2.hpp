// SPDX-License-Identifier: MIT
#pragma once
// Four float lanes in SSE2, for the wide kernels (avx2_target.hpp): the operations a kernel
// body uses, each the IEEE single-precision operation of the scalar code in every lane.
// lanes_avx2.hpp has the same names with eight lanes.
#include <cstdint>
#include <cstring>

#include <emmintrin.h>

namespace engine::render::soft::simd::sse2 {

struct Mask {
    __m128 v;
    // Bit i: lane i.
    [[gnu::always_inline]] std::uint32_t bits() const { return std::uint32_t(_mm_movemask_ps(v)); }
    [[gnu::always_inline]] bool any() const { return bits() != 0; }
    [[gnu::always_inline]] friend Mask operator&(Mask a, Mask b) { return {_mm_and_ps(a.v, b.v)}; }
    [[gnu::always_inline]] friend Mask operator|(Mask a, Mask b) { return {_mm_or_ps(a.v, b.v)}; }
    // Every lane of a where b is clear.
    [[gnu::always_inline]] friend Mask andNot(Mask a, Mask b) { return {_mm_andnot_ps(b.v, a.v)}; }
    // Lane i set where bit i of `bits` is.
    [[gnu::always_inline]] static Mask fromBits(std::uint32_t bits) {
        const __m128i lane = _mm_setr_epi32(1, 2, 4, 8);
        const __m128i b = _mm_set1_epi32(int(bits));
        return {_mm_castsi128_ps(_mm_cmpeq_epi32(_mm_and_si128(b, lane), lane))};
    }
};

struct Floats {
    static constexpr int kLanes = 4;
    __m128 v;
    [[gnu::always_inline]] static Floats splat(float x) { return {_mm_set1_ps(x)}; }
    [[gnu::always_inline]] static Floats load(const float* p) { return {_mm_loadu_ps(p)}; }
    // 0, 1, 2, 3
    [[gnu::always_inline]] static Floats laneIndex() { return {_mm_setr_ps(0.0f, 1.0f, 2.0f, 3.0f)}; }
    [[gnu::always_inline]] void store(float* p) const { _mm_storeu_ps(p, v); }
    [[gnu::always_inline]] friend Floats operator+(Floats a, Floats b) { return {_mm_add_ps(a.v, b.v)}; }
    [[gnu::always_inline]] friend Floats operator-(Floats a, Floats b) { return {_mm_sub_ps(a.v, b.v)}; }
    [[gnu::always_inline]] friend Floats operator*(Floats a, Floats b) { return {_mm_mul_ps(a.v, b.v)}; }
    [[gnu::always_inline]] friend Floats operator/(Floats a, Floats b) { return {_mm_div_ps(a.v, b.v)}; }
    [[gnu::always_inline]] friend Mask operator<(Floats a, Floats b) { return {_mm_cmplt_ps(a.v, b.v)}; }
    [[gnu::always_inline]] friend Mask operator>(Floats a, Floats b) { return {_mm_cmpgt_ps(a.v, b.v)}; }
    [[gnu::always_inline]] friend Mask operator>=(Floats a, Floats b) { return {_mm_cmpge_ps(a.v, b.v)}; }
};

[[gnu::always_inline]] inline Floats sqrt(Floats a) { return {_mm_sqrt_ps(a.v)}; }
// a > b ? a : b per lane (b where either is NaN): std::max(b, a) of the scalar code.
[[gnu::always_inline]] inline Floats maxOr(Floats a, Floats b) { return {_mm_max_ps(a.v, b.v)}; }
// a where m is set, +0 elsewhere.
[[gnu::always_inline]] inline Floats keepIf(Mask m, Floats a) { return {_mm_and_ps(m.v, a.v)}; }

// texels[int(y) * width + int(x)] in the lanes set in `active` (0 in the others), whose x and
// y lie in [0, 2^31) and whose index fits an int: one load per lane.
[[gnu::always_inline]] inline Floats gather(const float* texels, int width, Floats x, Floats y, Mask active) {
    alignas(16) float xs[4], ys[4], out[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    _mm_store_ps(xs, x.v);
    _mm_store_ps(ys, y.v);
    for (std::uint32_t bits = active.bits(); bits; bits &= bits - 1) {
        const int i = __builtin_ctz(bits);
        out[i] = texels[std::size_t(int(ys[i])) * std::size_t(width) + std::size_t(int(xs[i]))];
    }
    return {_mm_load_ps(out)};
}

}  // namespace engine::render::soft::simd::sse2
