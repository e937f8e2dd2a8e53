// SPDX-License-Identifier: MIT
// The trilinear level of detail (kernel/detail/texture_lod.hpp): lambda = log2(rho) from rho^2,
// against log2 in double precision over the whole range a sampler meets, exact at powers of
// two, and the four-lane form bit for bit the scalar one (the samplers' SIMD and general paths
// must agree to the bit).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "lcg.hpp"  // tests/support
#include "engine/render/kernel/detail/texture_lod.hpp"

namespace {

using engine::render::soft::textureLambda;
using ssam::testing::Lcg;

bool sameBits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// rho^2 in (1, 2^64): a random exponent and mantissa, so every binade is walked alike.
float randomRhoSquared(Lcg& rng) {
    const std::uint32_t exponent = 127 + std::uint32_t(rng.next() % 64);
    std::uint32_t bits = (exponent << 23) | std::uint32_t(rng.next() & 0x7FFFFF);
    float v;
    std::memcpy(&v, &bits, sizeof v);
    return v > 1.0f ? v : std::nextafter(1.0f, 2.0f);
}

TEST(TextureLod, WithinOneAndAHalfUlpOfLog2) {
    Lcg rng{20261207};
    double worstUlps = 0.0;
    for (int i = 0; i < 2'000'000; ++i) {
        const float r2 = randomRhoSquared(rng);
        const double exact = 0.5 * std::log2(double(r2));
        const float lambda = textureLambda(r2);
        // The spacing of floats at the result (an ulp), and at least that of 0.5 (tiny lambdas
        // come from rho^2 within a few ulps of 1, where rho^2's own rounding dominates).
        const double ulp = std::max(double(std::nextafter(float(exact), INFINITY)) - float(exact), 0x1p-24);
        worstUlps = std::max(worstUlps, std::abs(double(lambda) - exact) / ulp);
    }
    EXPECT_LE(worstUlps, 1.5) << "lambda strays from log2(rho) by more than rounding";
    RecordProperty("worst_ulps", std::to_string(worstUlps));
}

TEST(TextureLod, ExactAtPowersOfTwo) {
    for (int k = 0; k <= 62; ++k) {
        const float r2 = std::ldexp(1.0f, k + 1);  // rho^2 = 2^(k+1): lambda = (k + 1) / 2
        EXPECT_TRUE(sameBits(textureLambda(r2), 0.5f * float(k + 1))) << "rho^2 = 2^" << k + 1;
    }
    // +infinity (a derivative that overflowed) lands past every level, as log2 would.
    EXPECT_EQ(textureLambda(std::numeric_limits<float>::infinity()), 64.0f);
}

TEST(TextureLod, GrowsWithRho) {
    // Near each switch of the reduction (m = sqrt(2)) and each power of two, consecutive floats
    // give lambdas that never decrease: a level boundary is crossed once as a surface recedes.
    for (int e = 0; e < 40; ++e) {
        for (float centre : {std::ldexp(1.41421356f, e), std::ldexp(1.0f, e + 1)}) {
            float r2 = centre;
            for (int i = 0; i < 512; ++i) r2 = std::nextafter(r2, 0.0f);
            float previous = r2 > 1.0f ? textureLambda(r2) : 0.0f;
            for (int i = 0; i < 1024; ++i) {
                r2 = std::nextafter(r2, INFINITY);
                if (!(r2 > 1.0f)) continue;
                const float lambda = textureLambda(r2);
                ASSERT_GE(lambda, previous) << "rho^2 " << r2;
                previous = lambda;
            }
        }
    }
}

#if SOFT_TEXTURE_LOD_SSE2
TEST(TextureLod, FourLanesGiveTheScalarBits) {
    Lcg rng{7};
    for (int i = 0; i < 500'000; ++i) {
        alignas(16) float in[4], out[4];
        for (float& v : in) v = randomRhoSquared(rng);
        if (i == 0) in[3] = std::numeric_limits<float>::infinity();
        _mm_store_ps(out, engine::render::soft::textureLambda4(_mm_load_ps(in)));
        for (int k = 0; k < 4; ++k) ASSERT_TRUE(sameBits(out[k], textureLambda(in[k]))) << "rho^2 " << in[k];
    }
}
#endif

}  // namespace
