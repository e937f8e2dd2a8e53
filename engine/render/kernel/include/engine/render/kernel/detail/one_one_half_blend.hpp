// SPDX-License-Identifier: MIT
#pragma once
// The fast path of one family of blends: every factor ONE, the operation ADD or MAX on each half
// (BlendState::oneOne), onto a half-float target (R16F, RG16F, RGBA16F), for a program whose
// colour is its alpha replicated (kShadesReplicatedAlpha): coverage sums and maxima, e.g. the
// masks of [Hathaway 2010] §3.5.2 (Table 3.1) kept in float targets. The general path loads the
// texel, runs blend() and stores through storeTexel per pixel; these do the same per channel
// with the same bits. Float targets clamp nothing (GL 4.5 §17.3.6.1: only fixed-point targets
// clamp), so for the replicated colour (a, a, a, a) and the stored value d of a channel:
//   MAX  glm::max(a, d) = (a < d) ? d : a   (a, not d, where d is NaN; +0 over -0)
//   ADD  a * 1 + d * 1                        (the factors are exactly 1: a + d, unsaturated)
// then encodeHalf, which rounds to nearest even. Channels the write mask leaves keep their
// bits. (a is a saturated alpha, never NaN; the results do not depend on that, except which
// NaN an ADD of two NaNs gives.)
#include <cstddef>
#include <cstdint>
#include <cstring>

#include "engine/render/blend_state.hpp"
#include "engine/render/pixel_codec.hpp"
#include "half_float4.hpp"

namespace engine::render::soft {

// Whether a blend onto a target of this format is one these apply to: a half-float format
// and isOneOneAddMax (blend.hpp).
inline bool isHalfFloat(Format f) { return f == Format::R16F || f == Format::RG16F || f == Format::RGBA16F; }

// One pixel: `channels` halves at p (1, 2 or 4: R16F, RG16F, RGBA16F).
inline void blendOneOneHalf(const BlendState& b, std::byte* p, int channels, float a, std::uint8_t writeMask) {
    for (int c = 0; c < channels; ++c) {
        if (!(writeMask & (1u << c))) continue;
        std::uint16_t bits;
        std::memcpy(&bits, p + 2 * c, 2);
        const float d = decodeHalf(bits);
        const BlendOp op = c < 3 ? b.opRgb : b.opAlpha;
        const float out = op == BlendOp::Max ? (a < d ? d : a) : a * 1.0f + d * 1.0f;
        bits = encodeHalf(out);
        std::memcpy(p + 2 * c, &bits, 2);
    }
}

#if SOFT_HALF_FLOAT4_SSE2
// Four pixels, pixel i at p + i * 2 * channels with alpha lane i of `a`, for the lanes set in
// `lanes` (the others are neither read nor written, so lanes past a target's edge are
// safe). MAX is maxps(d, a), which is d where d > a and a otherwise (NaN, equal values and
// zeros of either sign included): (a < d) ? d : a.
inline void blendOneOneHalf4(const BlendState& b, std::byte* p, int channels, __m128 a, std::uint32_t lanes,
                             std::uint8_t writeMask) {
    const std::size_t pixelBytes = 2 * std::size_t(channels);
    const __m128 one = _mm_set1_ps(1.0f);
    for (int c = 0; c < channels; ++c) {
        if (!(writeMask & (1u << c))) continue;
        std::uint16_t stored[4] = {0, 0, 0, 0};
        for (std::uint32_t bits = lanes; bits; bits &= bits - 1) {
            const int i = __builtin_ctz(bits);
            std::memcpy(&stored[i], p + i * pixelBytes + 2 * c, 2);
        }
        const __m128 d = decodeHalf4(stored[0], stored[1], stored[2], stored[3]);
        const BlendOp op = c < 3 ? b.opRgb : b.opAlpha;
        const __m128 out = op == BlendOp::Max ? _mm_max_ps(d, a) : _mm_add_ps(_mm_mul_ps(a, one), _mm_mul_ps(d, one));
        alignas(16) std::uint32_t encoded[4];
        _mm_store_si128(reinterpret_cast<__m128i*>(encoded), encodeHalf4(out));
        for (std::uint32_t bits = lanes; bits; bits &= bits - 1) {
            const int i = __builtin_ctz(bits);
            const std::uint16_t h = std::uint16_t(encoded[i]);
            std::memcpy(p + i * pixelBytes + 2 * c, &h, 2);
        }
    }
}

// blendOneOneHalf4 for an R16F target with its channel written, where all four pixels lie
// inside the target (8 contiguous bytes at p): one load and one store, the pixels outside
// `lanes` stored back as they were.
inline void blendOneOneR16f4(const BlendState& b, std::byte* p, __m128 a, std::uint32_t lanes) {
    __m128i* at = reinterpret_cast<__m128i*>(p);
    const __m128i stored = _mm_loadl_epi64(at);
    const __m128 d = decodeHalf4(stored);
    const __m128 one = _mm_set1_ps(1.0f);
    const __m128 out = b.opRgb == BlendOp::Max ? _mm_max_ps(d, a) : _mm_add_ps(_mm_mul_ps(a, one), _mm_mul_ps(d, one));
    const __m128i blended = packHalf4(encodeHalf4(out));
    const __m128i bits = _mm_setr_epi16(1, 2, 4, 8, 0, 0, 0, 0);
    const __m128i write = _mm_cmpeq_epi16(_mm_and_si128(_mm_set1_epi16(short(lanes)), bits), bits);
    _mm_storel_epi64(at, _mm_or_si128(_mm_and_si128(write, blended), _mm_andnot_si128(write, stored)));
}

// blendOneOneHalf4 for an RGBA16F target: pixel by pixel, its four channels in one vector
// (MAX or ADD per channel as the blend says, then the write mask), one 8-byte load and store.
inline void blendOneOneRgba16f4(const BlendState& b, std::byte* p, __m128 a, std::uint32_t lanes,
                                std::uint8_t writeMask) {
    auto opMask = [&](int c) { return (c < 3 ? b.opRgb : b.opAlpha) == BlendOp::Max ? -1 : 0; };
    const __m128 useMax = _mm_castsi128_ps(_mm_setr_epi32(opMask(0), opMask(1), opMask(2), opMask(3)));
    auto written = [&](int c) { return short((writeMask >> c) & 1u ? -1 : 0); };
    const __m128i write = _mm_setr_epi16(written(0), written(1), written(2), written(3), 0, 0, 0, 0);
    const __m128 one = _mm_set1_ps(1.0f);
    alignas(16) float alpha[4];
    _mm_store_ps(alpha, a);
    for (std::uint32_t bits = lanes; bits; bits &= bits - 1) {
        const int i = __builtin_ctz(bits);
        __m128i* at = reinterpret_cast<__m128i*>(p + 8 * i);
        const __m128i stored = _mm_loadl_epi64(at);
        const __m128 d = decodeHalf4(stored);
        const __m128 ai = _mm_set1_ps(alpha[i]);
        const __m128 maxed = _mm_max_ps(d, ai), added = _mm_add_ps(_mm_mul_ps(ai, one), _mm_mul_ps(d, one));
        const __m128 out = _mm_or_ps(_mm_and_ps(useMax, maxed), _mm_andnot_ps(useMax, added));
        const __m128i blended = packHalf4(encodeHalf4(out));
        _mm_storel_epi64(at, _mm_or_si128(_mm_and_si128(write, blended), _mm_andnot_si128(write, stored)));
    }
}
#endif

}  // namespace engine::render::soft
