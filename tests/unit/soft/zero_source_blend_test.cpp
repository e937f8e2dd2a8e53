// SPDX-License-Identifier: MIT
// zeroSourceKeeps (raster_support.hpp): where it says a (0, 0, 0, 0) source leaves an 8-bit
// target as it is, the general path (loadTexel, blend(), storeTexel) must store back every
// byte it read, for +0 and -0 sources, every stored byte, every blend factor and operation
// (colour and alpha halves each), and any constant; and it must say so for the blends the
// composites use. A blend whose destination factor is not 1 for a zero source (SRC_ALPHA,
// ZERO, ...) would fail the byte check if it were let through.
// Program-authoring headers of the soft backend.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <vector>

#include "engine/render/kernel/detail/blend.hpp"
#include "engine/render/kernel/detail/raster_support.hpp"

namespace {

using namespace engine::render;
using namespace engine::render::soft;
using engine::render::soft::raster::zeroSourceKeeps;

struct Half {
    BlendFactor src, dst;
    BlendOp op;
};

std::vector<Half> everyHalf() {
    std::vector<Half> halves;
    for (BlendFactor s : kAllBlendFactors)
        for (BlendFactor d : kAllBlendFactors)
            for (BlendOp op : kAllBlendOps) halves.push_back({s, d, op});
    return halves;
}

// Every stored byte in every channel (channel c holds byte (b + 67 * c) % 256).
bool blendOfZeroKeepsEveryByte(Format format, const BlendState& b, const glm::vec4& constant) {
    const int bytes = formatInfo(format).bytesPerPixel;
    for (float zero : {0.0f, -0.0f}) {
        for (int v = 0; v < 256; ++v) {
            std::byte stored[4], p[4];
            for (int c = 0; c < 4; ++c) stored[c] = std::byte(std::uint8_t((v + 67 * c) % 256));
            std::memcpy(p, stored, sizeof p);
            storeTexel(p, format, blend(b, glm::vec4(zero), loadTexel(p, format), constant, true), b.writeMask);
            if (std::memcmp(p, stored, std::size_t(bytes)) != 0) return false;
        }
    }
    return true;
}

TEST(ZeroSourceBlend, WhereItIsSkippedItChangesNoByte) {
    const std::vector<Half> halves = everyHalf();
    const Half keep{BlendFactor::One, BlendFactor::InvSrcAlpha, BlendOp::Add};
    int skipped = 0;
    for (Format format : {Format::RGBA8_UNORM, Format::RGBA8_SRGB, Format::R8_UNORM, Format::RG8_UNORM}) {
        // Each half against every other combination of itself: the colour half varies with
        // the alpha half fixed to one that keeps, then the alpha half with the colour fixed.
        for (const Half& h : halves) {
            for (bool colourVaries : {true, false}) {
                const Half rgb = colourVaries ? h : keep, alpha = colourVaries ? keep : h;
                BlendState b{true, rgb.src, rgb.dst, rgb.op, alpha.src, alpha.dst, alpha.op, WriteAll};
                if (!zeroSourceKeeps(format, b)) continue;
                ++skipped;
                for (const glm::vec4 constant : {glm::vec4(0.0f), glm::vec4(0.3f, 1.0f, 0.0f, 0.7f), glm::vec4(2.0f)})
                    ASSERT_TRUE(blendOfZeroKeepsEveryByte(format, b, constant))
                        << formatInfo(format).name << ": rgb " << int(rgb.src) << "/" << int(rgb.dst) << " op "
                        << int(rgb.op) << ", alpha " << int(alpha.src) << "/" << int(alpha.dst) << " op "
                        << int(alpha.op);
            }
        }
    }
    EXPECT_GT(skipped, 500);  // source factors of every kind are let through with ADD or MAX
}

TEST(ZeroSourceBlend, TheCompositesBlendsAreSkippedAndOthersAreNot) {
    EXPECT_TRUE(zeroSourceKeeps(Format::RGBA8_SRGB, BlendState::premultipliedOver()));  // the particle layer
    EXPECT_TRUE(zeroSourceKeeps(Format::RGBA8_UNORM, BlendState::maxRgbAddAlpha()));    // SSAM's mask
    EXPECT_TRUE(zeroSourceKeeps(Format::RGBA8_SRGB, BlendState::alphaOver()));
    // A float target keeps -0 and NaN as they are only where the source adds nothing: not skipped.
    EXPECT_FALSE(zeroSourceKeeps(Format::RGBA16F, BlendState::premultipliedOver()));
    BlendState subtract = BlendState::premultipliedOver();
    subtract.opRgb = BlendOp::Subtract;  // 0 - d
    EXPECT_FALSE(zeroSourceKeeps(Format::RGBA8_UNORM, subtract));
    BlendState replace = BlendState::premultipliedOver();
    replace.dstAlpha = BlendFactor::SrcAlpha;  // d * 0
    EXPECT_FALSE(zeroSourceKeeps(Format::RGBA8_UNORM, replace));
}

}  // namespace
