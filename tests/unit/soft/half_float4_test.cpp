// SPDX-License-Identifier: MIT
// The soft backend's SSE2 half-float conversions and ONE/ONE half-float blends
// (half_float4.hpp, one_one_half_blend.hpp) against the general codec and blend, bit for
// bit: decodeHalf4 for every half; encodeHalf4 for every float whose low 13 bits are one of
// the patterns that decide its rounding (so every sign, exponent and kept mantissa, ties,
// just-below and just-above ties, NaN payloads, infinities, overflow, denormal results and
// float denormals), plus random floats; and blendOneOneHalf, blendOneOneHalf4,
// blendOneOneR16f4 and blendOneOneRgba16f4 against blend() + storeTexel for every stored
// half (NaN, Inf, -0, denormals included) under MAX and ADD, every half-float format and
// write mask.
// With SSAM_EXHAUSTIVE_HALF=1 the encode test checks all 2^32 floats instead (about 20 s;
// it passed when the code was written).
// Program-authoring headers (engine_render_kernel).
#include "lcg.hpp"  // tests/support
#include "engine/render/kernel/detail/half_float4.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "engine/render/kernel/detail/blend.hpp"
#include "engine/render/kernel/detail/one_one_half_blend.hpp"

namespace {

using namespace engine::render;
using namespace engine::render::soft;

using ssam::testing::Lcg;

float fromBits(std::uint32_t b) {
    float f;
    std::memcpy(&f, &b, sizeof f);
    return f;
}
std::uint32_t bitsOf(float f) {
    std::uint32_t b;
    std::memcpy(&b, &f, sizeof b);
    return b;
}

#if SOFT_HALF_FLOAT4_SSE2
// encodeHalf4 + packHalf4 of four floats given as bits; counts (and reports the first few)
// lanes that differ from encodeHalf.
int encodeMismatches(const std::uint32_t* in, int& reported) {
    alignas(16) std::uint32_t lanes[4];
    std::memcpy(lanes, in, sizeof lanes);
    const __m128i encoded = encodeHalf4(_mm_load_ps(reinterpret_cast<const float*>(lanes)));
    alignas(16) std::uint32_t wide[4];
    _mm_store_si128(reinterpret_cast<__m128i*>(wide), encoded);
    alignas(16) std::uint16_t packed[8];
    _mm_store_si128(reinterpret_cast<__m128i*>(packed), packHalf4(encoded));
    int bad = 0;
    for (int i = 0; i < 4; ++i) {
        const std::uint16_t expected = encodeHalf(fromBits(lanes[i]));
        if (wide[i] != expected || packed[i] != expected) {
            ++bad;
            if (reported++ < 10)
                ADD_FAILURE() << std::hex << "float 0x" << lanes[i] << ": encodeHalf 0x" << expected
                              << ", encodeHalf4 0x" << wide[i] << ", packed 0x" << packed[i];
        }
    }
    return bad;
}

TEST(SoftHalfFloat4, DecodeMatchesDecodeHalfForEveryHalf) {
    for (std::uint32_t h = 0; h < 0x10000; h += 4) {
        alignas(16) float out[4];
        _mm_store_ps(out,
                     decodeHalf4(std::uint16_t(h), std::uint16_t(h + 1), std::uint16_t(h + 2), std::uint16_t(h + 3)));
        for (std::uint32_t i = 0; i < 4; ++i)
            ASSERT_EQ(bitsOf(out[i]), bitsOf(decodeHalf(std::uint16_t(h + i)))) << std::hex << "half 0x" << h + i;
    }
}

TEST(SoftHalfFloat4, EncodeMatchesEncodeHalfOnEveryRoundingCase) {
    int reported = 0;
    long bad = 0, checked = 0;
    std::uint32_t batch[4];
    int n = 0;
    auto check = [&](std::uint32_t bits) {
        batch[n++] = bits;
        if (n < 4) return;
        bad += encodeMismatches(batch, reported);
        checked += 4;
        n = 0;
    };
    if (std::getenv("SSAM_EXHAUSTIVE_HALF")) {  // every float
        for (std::uint64_t b = 0; b < (1ull << 32); ++b) check(std::uint32_t(b));
        EXPECT_EQ(bad, 0) << "of " << checked << " floats";
        return;
    }
    // encodeHalf keeps at most the top 10 mantissa bits (fewer for denormal results) and
    // rounds on the rest: bit 12 is the round bit of a normal result, bits 0..11 its sticky
    // bits, bit 13 the kept bit that breaks ties. Every value of bits 13..31 with these low
    // patterns covers each case of every exponent; denormal results round on higher bits,
    // which the high part enumerates (ties: low bits 0).
    const std::uint32_t lows[] = {0x0000, 0x0001, 0x0800, 0x0FFF, 0x1000, 0x1001, 0x1800, 0x1FFF};
    for (std::uint32_t high = 0; high < (1u << 19); ++high)
        for (std::uint32_t low : lows) check((high << 13) | low);
    Lcg rng{31};
    for (int i = 0; i < (1 << 22); ++i) check(rng.next() ^ (rng.next() << 16));
    EXPECT_EQ(bad, 0) << "of " << checked << " floats";
    EXPECT_EQ(checked, (1L << 19) * 8 + (1L << 22));
}
#endif

// The general path's result: loadTexel, blend() with the float target rules, storeTexel.
void generalBlend(const BlendState& b, std::byte* p, Format format, float a, std::uint8_t writeMask) {
    storeTexel(p, format, blend(b, glm::vec4(a), loadTexel(p, format), glm::vec4(0.0f), false), writeMask);
}

int channelsOf(Format f) { return f == Format::R16F ? 1 : f == Format::RG16F ? 2 : 4; }

// Alphas the mask program produces (saturated: [0, 1], never NaN), denormals and ties of
// the half rounding included, and a few beyond [0, 1] (the functions take any non-NaN a).
std::vector<float> alphas(Lcg& rng) {
    // 2^-25 rounds (a tie) to 0 and 2^-24 is the least half; 1e-40 is a float denormal;
    // 2^-11 and 1 + 2^-11 are ties of the rounding near 0.5 and 1.
    std::vector<float> a = {0.0f, 1.0f, 0.5f, 1.0f / 3.0f, 0.999f, 1e-40f, fromBits(0x33000000), fromBits(0x33800000)};
    for (float v : {6.1e-5f, 0.00048828125f, 1.00048828125f, 2.5f, -0.25f, 70000.0f}) a.push_back(v);
    for (int i = 0; i < 16; ++i) a.push_back(rng.unit());
    return a;
}

std::vector<BlendState> oneOneBlends() {
    std::vector<BlendState> blends;
    for (BlendOp rgb : {BlendOp::Max, BlendOp::Add})
        for (BlendOp alpha : {BlendOp::Max, BlendOp::Add})
            blends.push_back(
                {true, BlendFactor::One, BlendFactor::One, rgb, BlendFactor::One, BlendFactor::One, alpha, WriteAll});
    return blends;
}

TEST(SoftOneOneHalfBlend, ScalarMatchesGeneralBlendForEveryStoredHalf) {
    Lcg rng{5};
    const std::vector<float> as = alphas(rng);
    long checked = 0;
    for (Format format : {Format::R16F, Format::RG16F, Format::RGBA16F}) {
        const int channels = channelsOf(format);
        for (BlendState b : oneOneBlends()) {
            ASSERT_TRUE(isOneOneAddMax(b));
            for (std::uint8_t mask : {std::uint8_t(WriteAll), std::uint8_t(WriteA | 1u), std::uint8_t(2u)}) {
                b.writeMask = mask;
                for (std::uint32_t h = 0; h < 0x10000; ++h) {
                    const float a = as[h % as.size()];
                    std::byte general[8], fast[8];
                    for (int c = 0; c < 4; ++c) {  // channel c holds h, h ^ c * 0x4321 (others differ)
                        const std::uint16_t bits = std::uint16_t(h ^ (c * 0x4321u));
                        std::memcpy(general + 2 * c, &bits, 2);
                    }
                    std::memcpy(fast, general, sizeof fast);
                    generalBlend(b, general, format, a, mask);
                    blendOneOneHalf(b, fast, channels, a, mask);
                    ASSERT_EQ(std::memcmp(general, fast, 2 * channels), 0)
                        << formatName(format) << std::hex << " stored 0x" << h << " alpha bits 0x" << bitsOf(a)
                        << " mask 0x" << int(mask) << " ops " << int(b.opRgb) << "/" << int(b.opAlpha);
                    ++checked;
                }
            }
        }
    }
    EXPECT_EQ(checked, 3L * 4 * 3 * 0x10000);
}

#if SOFT_HALF_FLOAT4_SSE2
TEST(SoftOneOneHalfBlend, FourLanesMatchGeneralBlendAndLeaveOtherLanes) {
    Lcg rng{9};
    const std::vector<float> as = alphas(rng);
    for (Format format : {Format::R16F, Format::RG16F, Format::RGBA16F}) {
        const int channels = channelsOf(format), pixelBytes = 2 * channels;
        for (BlendState b : oneOneBlends()) {
            for (std::uint8_t mask : {std::uint8_t(WriteAll), std::uint8_t(WriteRGB), std::uint8_t(WriteA | 2u)}) {
                b.writeMask = mask;
                // Every stored half appears in every lane and channel over the loop.
                for (std::uint32_t h = 0; h < 0x10000; ++h) {
                    std::byte before[4 * 8], general[4 * 8], fast[4 * 8];
                    for (int i = 0; i < 4 * channels; ++i) {
                        const std::uint16_t bits = std::uint16_t(i == 0 ? h : (h * (i + 7)) ^ rng.next());
                        std::memcpy(before + 2 * i, &bits, 2);
                    }
                    alignas(16) float a[4];
                    for (float& v : a) v = as[rng.next() % as.size()];
                    const std::uint32_t lanes = (h & 0xF) | 1u;  // lane 0 always, the others in every combination
                    std::memcpy(general, before, sizeof before);
                    std::memcpy(fast, before, sizeof before);
                    for (int i = 0; i < 4; ++i)
                        if ((lanes >> i) & 1u) generalBlend(b, general + i * pixelBytes, format, a[i], mask);
                    blendOneOneHalf4(b, fast, channels, _mm_load_ps(a), lanes, mask);
                    ASSERT_EQ(std::memcmp(general, fast, std::size_t(4 * pixelBytes)), 0)
                        << formatName(format) << std::hex << " stored 0x" << h << " lanes 0x" << lanes << " mask 0x"
                        << int(mask) << " ops " << int(b.opRgb) << "/" << int(b.opAlpha);
                    ASSERT_EQ(std::memcmp(fast + 4 * pixelBytes, before + 4 * pixelBytes,
                                          sizeof before - std::size_t(4 * pixelBytes)),
                              0);
                    if (format == Format::R16F && (mask & 1u)) {  // the whole-row R16F variant
                        std::memcpy(fast, before, sizeof before);
                        blendOneOneR16f4(b, fast, _mm_load_ps(a), lanes);
                        ASSERT_EQ(std::memcmp(general, fast, sizeof fast), 0)
                            << "blendOneOneR16f4" << std::hex << " stored 0x" << h << " lanes 0x" << lanes << " op "
                            << int(b.opRgb);
                    }
                    if (format == Format::RGBA16F) {
                        std::memcpy(fast, before, sizeof before);
                        blendOneOneRgba16f4(b, fast, _mm_load_ps(a), lanes, mask);
                        ASSERT_EQ(std::memcmp(general, fast, sizeof fast), 0)
                            << "blendOneOneRgba16f4" << std::hex << " stored 0x" << h << " lanes 0x" << lanes
                            << " mask 0x" << int(mask) << " ops " << int(b.opRgb) << "/" << int(b.opAlpha);
                    }
                }
            }
        }
    }
}
#endif

}  // namespace
