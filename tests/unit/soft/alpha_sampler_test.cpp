// SPDX-License-Identifier: MIT
// The soft backend's fast samplers against the general one, bit for bit: AlphaSampler's
// scalar sample() and its SIMD lookup4 + alpha4 / rgba4 (the mask pass and the alpha-tested
// colour pass) must give exactly sampleTexture<AlphaOnly> / sampleTexture<All> for every
// filter, address mode, format, size (power of two or not, 1-texel levels), with and without
// the decoded alpha copy, at random coordinates and derivatives (magnified and minified,
// texel edges, non-finite values). The golden hashes only see the few cases their scenes
// hit; this walks the whole space of the sampler's branches.
// The samplers come from the program-authoring headers (engine_render_kernel).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

#include <gtest/gtest.h>

#include "lcg.hpp"         // tests/support
#include "soft_image.hpp"  // tests/support
#include "engine/render/kernel/alpha_sampler.hpp"
#include "engine/render/kernel/sampler.hpp"

namespace {

using namespace engine::render;
using namespace engine::render::soft;

using ssam::testing::Lcg;

bool sameBits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// Random texels, about a third of them with alpha 0 (as foliage has); `sampledOnly` textures
// get the decoded alpha copy, render targets do not.
SoftTexture texture(int w, int h, int levels, Format format, bool sampledOnly, Lcg& rng) {
    SoftTexture t;
    t.desc.width = w;
    t.desc.height = h;
    t.desc.format = format;
    t.desc.mipLevels = levels;
    t.desc.usage = std::uint8_t(sampledOnly ? UsageSampled : UsageSampled | UsageRenderTarget);
    t.bytesPerSample = 4;
    for (int l = 0; l < levels; ++l) {
        MipLevel m;
        m.width = std::max(1, w >> l);
        m.height = std::max(1, h >> l);
        m.texels.resize(std::size_t(m.width) * m.height * 4);
        for (std::size_t i = 0; i < m.texels.size(); ++i)
            m.texels[i] = std::byte(i % 4 == 3 && rng.next() % 3 == 0 ? 0 : rng.next() & 0xFF);
        t.levels.push_back(std::move(m));
    }
    t.copyDecoded();
    return t;
}

int fullChain(int w, int h) {
    int levels = 1;
    while ((std::max(w, h) >> levels) > 0) ++levels;
    return levels;
}

TEST(SoftAlphaSampler, MatchesTheGeneralSamplerBitForBit) {
    Lcg rng{2024};
    const int sizes[][2] = {{64, 64}, {256, 128}, {1, 1}, {2, 64}, {16, 1}, {48, 40}, {37, 19}};
    int simdConfigurations = 0;
    for (const auto& size : sizes)
        for (Format format : {Format::RGBA8_UNORM, Format::RGBA8_SRGB})
            for (bool sampledOnly : {true, false})
                for (int filter = 0; filter < 3; ++filter)
                    for (int u = 0; u < 3; ++u)
                        for (int v = 0; v < 3; ++v)
                            for (int levels : {1, fullChain(size[0], size[1])}) {
                                const SoftTexture t = texture(size[0], size[1], levels, format, sampledOnly, rng);
                                SamplerState s;
                                s.filter = Filter(filter);
                                s.addressU = AddressMode(u);
                                s.addressV = AddressMode(v);
                                const AlphaSampler sampler(t, s);
                                ASSERT_TRUE(sampler.valid());
                                simdConfigurations += sampler.simd4();
                                SCOPED_TRACE(testing::Message()
                                             << size[0] << "x" << size[1] << " levels " << levels << " filter "
                                             << filter << " address " << u << v << " sRGB "
                                             << (format == Format::RGBA8_SRGB) << " copy " << sampledOnly);
                                for (int it = 0; it < 300; ++it) {
                                    alignas(16) float uu[4], vv[4], dudx[4], dvdx[4], dudy[4], dvdy[4];
                                    const float scale = std::exp2(rng.range(-8.0f, 8.0f));
                                    for (int i = 0; i < 4; ++i) {
                                        uu[i] = rng.range(-3.0f, 3.0f);
                                        vv[i] = rng.range(-3.0f, 3.0f);
                                        if (it % 7 == 0) uu[i] = std::floor(uu[i] * float(size[0])) / float(size[0]);
                                        if (it % 11 == 0)
                                            vv[i] = (std::floor(vv[i] * float(size[1])) + 0.5f) / float(size[1]);
                                        dudx[i] = rng.range(-0.3f, 0.3f) * scale;
                                        dvdx[i] = rng.range(-0.3f, 0.3f) * scale;
                                        dudy[i] = rng.range(-0.3f, 0.3f) * scale;
                                        dvdy[i] = rng.range(-0.3f, 0.3f) * scale;
                                    }
                                    if (it == 5) uu[0] = NAN, vv[1] = INFINITY, uu[2] = -1e30f, dudx[3] = NAN;
                                    glm::vec4 general[4];
                                    for (int i = 0; i < 4; ++i) {
                                        const UvDerivatives d{{dudx[i], dvdx[i]}, {dudy[i], dvdy[i]}};
                                        general[i] = sampleTexture(t, s, {uu[i], vv[i]}, d);
                                        const float alphaOnly =
                                            sampleTexture<SampledChannels::AlphaOnly>(t, s, {uu[i], vv[i]}, d).a;
                                        ASSERT_TRUE(sameBits(alphaOnly, general[i].a));
                                        ASSERT_TRUE(sameBits(sampler.sample({uu[i], vv[i]}, d), alphaOnly));
                                    }
#if SOFT_SAMPLER_SSE2
                                    if (!sampler.simd4()) continue;
                                    const std::uint32_t lanes = it % 5 == 0 ? (rng.next() & 0xFu) | 1u : 0xFu;
                                    const AlphaSampler::Lookup4 lookup =
                                        sampler.lookup4(uu, vv, dudx, dvdx, dudy, dvdy, lanes);
                                    alignas(16) float alpha[4], rgba[4][4];
                                    _mm_store_ps(alpha, sampler.alpha4(lookup));
                                    sampler.rgba4(lookup, lanes, rgba);
                                    for (int i = 0; i < 4; ++i) {
                                        if (!((lanes >> i) & 1u)) continue;
                                        ASSERT_TRUE(sameBits(alpha[i], general[i].a)) << "lane " << i;
                                        for (int c = 0; c < 4; ++c)
                                            ASSERT_TRUE(sameBits(rgba[i][c], general[i][c]))
                                                << "lane " << i << " channel " << c;
                                    }
#endif
                                }
                            }
#if SOFT_SAMPLER_SSE2
    EXPECT_GT(simdConfigurations, 0);  // the SIMD path was exercised
#endif
}

// The four-channel decoded copy is kept up to kDecodedCopyMaxTexels texels and not beyond; the
// alpha copy always. (Both paths of the colour taps are compared with the general sampler above.)
TEST(SoftAlphaSampler, FourChannelCopyOnlyUpToItsSize) {
    auto levelsOf = [](int w, int h) {
        SoftTexture t = ssam::testing::softImage(w, h, Format::RGBA8_SRGB, 4);
        t.desc.usage = UsageSampled;
        std::fill(t.levels[0].texels.begin(), t.levels[0].texels.end(), std::byte{0x80});
        t.copyDecoded();
        return t;
    };
    const SoftTexture atCap = levelsOf(2048, 2048), beyond = levelsOf(2049, 2048);
    EXPECT_EQ(atCap.levels[0].rgba.size(), std::size_t(4) * 2048 * 2048);
    EXPECT_EQ(atCap.levels[0].alpha.size(), std::size_t(2048) * 2048);
    EXPECT_TRUE(beyond.levels[0].rgba.empty());
    EXPECT_EQ(beyond.levels[0].alpha.size(), std::size_t(2049) * 2048);
    EXPECT_EQ(atCap.levels[0].rgba[4], byteTables().srgb[0x80]);
    EXPECT_EQ(atCap.levels[0].rgba[7], byteTables().unorm[0x80]);
}

}  // namespace
