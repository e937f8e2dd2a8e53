// SPDX-License-Identifier: MIT
// The lit surface programs' four-lane shading and the four-lane 8-bit encodes against the
// scalar code they stand in for, bit for bit: SurfaceProgram::shadeSampled4 against
// shadeSampled() lane by lane (opaque and alpha-masked, front and back faces, straight and
// premultiplied textures, random and degenerate normals: zero, NaN, pointing away from the
// light), and encodeSrgb8x4 / encodeUnorm8x4 against encodeSrgb8 / encodeUnorm8 on random
// and special floats. The rasterizer's packed writes (shadePacked4) are these, then the
// stores writeShaded makes; the racer goldens cover those in whole frames.
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "lcg.hpp"         // tests/support
#include "soft_image.hpp"  // tests/support
#include "engine/render/kernel/programs.hpp"
#include "engine/render/kernel/detail/raster_support.hpp"

#if SOFT_SAMPLER_SSE2 && SOFT_RASTER_SSE2
namespace {

using namespace engine::render;
using namespace engine::render::soft;

using ssam::testing::Lcg;

// The same bits, except that any two NaNs match: IEEE 754-2008 §6.3 leaves the sign of a NaN
// result unspecified. x86 makes a new NaN (0 * inf) negative and passes an input NaN through
// unchanged, so which one a lane ends with follows the order the compiler evaluated the
// operations in, and a ThreadSanitizer build orders some differently from the release build.
bool sameValue(float a, float b) { return (std::isnan(a) && std::isnan(b)) || std::memcmp(&a, &b, sizeof a) == 0; }

float uniform(Lcg& rng, float lo, float hi) { return lo + (hi - lo) * float(rng.next() % 100000) / 100000.0f; }

// A value as shading meets it: mostly ordinary, sometimes 0, -0, NaN, infinite or huge.
float attribute(Lcg& rng, float lo, float hi) {
    switch (rng.next() % 24) {
        case 0: return 0.0f;
        case 1: return -0.0f;
        case 2: return std::numeric_limits<float>::quiet_NaN();
        case 3: return std::numeric_limits<float>::infinity();
        case 4: return 3.0e38f;
        default: return uniform(rng, lo, hi);
    }
}

SoftTexture oneTexel(AlphaMode mode) {
    SoftTexture t = ssam::testing::softImage(1, 1, Format::RGBA8_SRGB, 4);
    t.desc.alpha = mode;
    t.copyDecoded();
    return t;
}

template <bool AlphaMasked>
void expectShade4MatchesShadeSampled(AlphaMode mode, std::uint64_t seed) {
    Lcg rng{seed};
    const SoftTexture texture = oneTexel(mode);
    int mismatches = 0;
    for (int round = 0; round < 4000; ++round) {
        SurfaceParams params;
        params.baseColorFactor = {uniform(rng, 0.0f, 1.5f), uniform(rng, 0.0f, 1.5f), uniform(rng, 0.0f, 1.5f),
                                  uniform(rng, 0.0f, 1.0f)};
        params.light.towardLight = {uniform(rng, -1.0f, 1.0f), uniform(rng, -1.0f, 1.0f), uniform(rng, -1.0f, 1.0f)};
        params.light.color = {uniform(rng, 0.0f, 2.0f), uniform(rng, 0.0f, 2.0f), uniform(rng, 0.0f, 2.0f)};
        params.light.ambient = {uniform(rng, 0.0f, 1.0f), uniform(rng, 0.0f, 1.0f), uniform(rng, 0.0f, 1.0f)};
        const SurfaceProgram<AlphaMasked> program(params, &texture);
        const bool frontFacing = rng.next() % 2 == 0;
        alignas(16) float texels[4][4], color[4][4], normal[3][4];  // texels by lane, the rest by channel
        for (int i = 0; i < 4; ++i) {
            for (int c = 0; c < 4; ++c) texels[i][c] = rng.next() % 16 == 0 ? 0.0f : uniform(rng, 0.0f, 1.0f);
            for (int c = 0; c < 4; ++c) color[c][i] = attribute(rng, 0.0f, 1.0f);
            for (int k = 0; k < 3; ++k) normal[k][i] = attribute(rng, -1.0f, 1.0f);
        }
        __m128 texel[4] = {_mm_setr_ps(texels[0][0], texels[1][0], texels[2][0], texels[3][0]),
                           _mm_setr_ps(texels[0][1], texels[1][1], texels[2][1], texels[3][1]),
                           _mm_setr_ps(texels[0][2], texels[1][2], texels[2][2], texels[3][2]),
                           _mm_setr_ps(texels[0][3], texels[1][3], texels[2][3], texels[3][3])};
        const float* const colorAt[4] = {color[0], color[1], color[2], color[3]};
        const float* const normalAt[3] = {normal[0], normal[1], normal[2]};
        __m128 out[4];
        program.shadeSampled4(texel, colorAt, normalAt, frontFacing, out);
        alignas(16) float got[4][4];
        for (int c = 0; c < 4; ++c) _mm_store_ps(got[c], out[c]);
        for (int i = 0; i < 4; ++i) {
            Fragment f;
            f.frontFacing = frontFacing;
            f.color = {color[0][i], color[1][i], color[2][i], color[3][i]};
            f.normal = {normal[0][i], normal[1][i], normal[2][i]};
            const glm::vec4 want =
                program.shadeSampled(f, glm::vec4(texels[i][0], texels[i][1], texels[i][2], texels[i][3]));
            for (int c = 0; c < 4; ++c)
                if (!sameValue(got[c][i], want[c]) && ++mismatches <= 5)
                    ADD_FAILURE() << "round " << round << " lane " << i << " channel " << c << ": four-lane "
                                  << got[c][i] << ", scalar " << want[c];
        }
    }
    EXPECT_EQ(mismatches, 0);
}

TEST(SurfaceShade4, OpaqueMatchesShadeSampled) { expectShade4MatchesShadeSampled<false>(AlphaMode::Straight, 11); }
TEST(SurfaceShade4, MaskedMatchesShadeSampled) { expectShade4MatchesShadeSampled<true>(AlphaMode::Straight, 12); }
TEST(SurfaceShade4, PremultipliedTextureMatchesShadeSampled) {
    expectShade4MatchesShadeSampled<false>(AlphaMode::Premultiplied, 13);
    expectShade4MatchesShadeSampled<true>(AlphaMode::Premultiplied, 14);
}

// encodeSrgb8x4 / encodeUnorm8x4 against the scalar encodes: random floats over [-0.5, 1.5],
// every bit pattern near the sRGB steps, and the special values.
TEST(SurfaceShade4, EncodesMatchTheScalarEncodes) {
    using raster::encodeSrgb8x4;
    using raster::encodeUnorm8x4;
    std::vector<float> values = {0.0f,
                                 -0.0f,
                                 1.0f,
                                 std::nextafter(1.0f, 0.0f),
                                 1.5f,
                                 -1.0f,
                                 1.0e-40f,
                                 std::numeric_limits<float>::quiet_NaN(),
                                 std::numeric_limits<float>::infinity(),
                                 -std::numeric_limits<float>::infinity()};
    Lcg rng{15};
    for (int i = 0; i < 200000; ++i) values.push_back(uniform(rng, -0.5f, 1.5f));
    const SrgbEncodeTables& tables = srgbEncodeTables();
    for (int k = 1; k < 256; ++k)
        for (float v = tables.threshold[k], n = 0; n < 4; ++n, v = std::nextafter(v, 0.0f)) values.push_back(v);
    while (values.size() % 4) values.push_back(0.5f);
    int mismatches = 0;
    for (std::size_t i = 0; i < values.size(); i += 4) {
        const __m128 v = _mm_loadu_ps(&values[i]);
        alignas(16) std::int32_t srgb[4], unorm[4];
        _mm_store_si128(reinterpret_cast<__m128i*>(srgb), encodeSrgb8x4(v));
        _mm_store_si128(reinterpret_cast<__m128i*>(unorm), encodeUnorm8x4(v));
        for (int k = 0; k < 4; ++k) {
            const float x = values[i + k];
            if ((srgb[k] != encodeSrgb8(x) || unorm[k] != encodeUnorm8(x)) && ++mismatches <= 5)
                ADD_FAILURE() << "value " << x << ": sRGB " << srgb[k] << " (scalar " << int(encodeSrgb8(x))
                              << "), UNORM " << unorm[k] << " (scalar " << int(encodeUnorm8(x)) << ")";
        }
    }
    EXPECT_EQ(mismatches, 0);
}

}  // namespace
#endif
