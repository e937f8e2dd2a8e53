// SPDX-License-Identifier: MIT
#pragma once
// TriangleRasterizer's constant fragments: a triangle whose interpolants are all constant is
// shaded once, its alpha test and stored bytes worked out once, and blended through a
// per-thread table of the bytes it stores.
#include "engine/render/kernel/detail/rasterizer/rasterizer_class.hpp"

namespace engine::render::soft {
namespace raster {
namespace {  // as raster_support.hpp's

// A plane whose slopes are zero evaluates to exactly its value at every pixel centre
// (value + (+-0) + (+-0) == value for finite pixel offsets), unless the value is -0.0,
// which would come out +0.0.
template <typename Program>
inline bool TriangleRasterizer<Program>::constantPlane(const Plane& p) {
    return p.dx == 0.0f && p.dy == 0.0f && !(p.value == 0.0f && std::signbit(p.value));
}

// When every plane the program reads is constant, the fragment and so the shaded colour
// are the same at every pixel (programs are pure functions of the fragment; Composite
// reads textures by pixel position and is excluded): the program runs once per
// triangle, and the alpha test and the stored bytes are worked out once.
template <typename Program>
inline void TriangleRasterizer<Program>::prepareConstant(const SetupTriangle& t, int boxPixels) {
    constant_ = false;
    if (draw_.capture) return;  // captured fragments each carry their own depth
    if constexpr (readsPixels<Program>()) {
        return;
    } else {
        constexpr ProgramNeeds needs = Program::kNeeds;
        if constexpr (needs.anyAttribute()) {
            if (!constantPlane(t.inverseW)) return;
        }
        if constexpr (needs.uv) {
            if (!constantPlane(t.attributeOverW[kAttrU]) || !constantPlane(t.attributeOverW[kAttrV])) return;
        }
        if constexpr (needs.normal) {
            for (int k = 0; k < 3; ++k)
                if (!constantPlane(t.attributeOverW[kAttrNormal + k])) return;
        }
        if constexpr (needs.color) {
            for (int k = 0; k < 4; ++k)
                if (!constantPlane(t.attributeOverW[kAttrColor + k])) return;
        }
        if constexpr (needs.colorAlpha) {
            if (!constantPlane(t.attributeOverW[kAttrColor + 3])) return;
        }
    }
    constant_ = true;
    const glm::vec4 color = program_.shade(interpolate(t, 0, 0, 0.0f, 0.0f));
    constantColor_ = color;
    const AlphaTestWrites writes = alphaTestWrites(draw_.alphaTest, color.a, draw_.depthWrite);
    constantDiscard_ = writes.discard;
    constantDepthWrite_ = writes.depth;
    for (int i = 0; i < draw_.colorTargetCount; ++i) {
        const TargetView& target = color_[i];
        constantMask_[i] = draw_.blend[i].writeMask & writes.channels;
        if (target.rgba8Plain) {
            std::byte bytes[4];
            storeRgba8Unorm(bytes, color);
            std::memcpy(&constantPacked_[i], bytes, 4);
        }
        // Blends through a table only for triangles large enough to repay building it.
        useLut_[i] = target.byteLut && boxPixels >= kBlendLutMinPixels;
        if (useLut_[i] && !tBlendLuts[i].matches(draw_.blend[i], draw_.blendConstant, target.format, color))
            buildBlendLut(i, color);
    }
}

// bytes[c][k]: the byte stored into channel c of target i over a stored byte k, blending
// the constant colour: exactly what loadTexel + blend + storeTexel give per pixel, as
// (blendIsPerChannel) channel c of the result reads only channel c of the destination.
template <typename Program>
inline void TriangleRasterizer<Program>::buildBlendLut(int i, const glm::vec4& color) {
    const TargetView& target = color_[i];
    BlendLut& lut = tBlendLuts[i];
    lut.valid = true;
    lut.blend = draw_.blend[i];
    lut.constant = draw_.blendConstant;
    lut.format = target.format;
    lut.color = color;
    for (int k = 0; k < 256; ++k) {
        std::byte dst[4] = {std::byte(k), std::byte(k), std::byte(k), std::byte(k)};
        const glm::vec4 out =
            blend(draw_.blend[i], color, loadTexel(dst, target.format), draw_.blendConstant, target.normalized);
        storeTexel(dst, target.format, out, 0xF);
        for (int c = 0; c < 4; ++c) lut.bytes[c][k] = dst[c];
    }
}

// Writes of the constant-colour fragment at the `live` pixels of a block row (bit i:
// pixel bx + i), which passed coverage and depth; target by target, as the per-pixel
// path does (each pixel's bytes depend only on that pixel).
template <typename Program>
inline void TriangleRasterizer<Program>::writeConstantRow(int bx, int py, std::uint32_t live, const float* z,
                                                          std::byte* depthAt) {
    if (constantDepthWrite_)
        for (std::uint32_t bits = live; bits; bits &= bits - 1) {
            const int k = __builtin_ctz(bits);
            std::memcpy(depthAt + k * sizeof(float), &z[k], sizeof(float));
        }
    for (int i = 0; i < draw_.colorTargetCount; ++i) {
        const std::uint8_t mask = constantMask_[i];
        if (!mask) continue;
        const TargetView& target = color_[i];
        std::byte* row = target.at(bx, py);
        if (target.rgba8Plain && mask == WriteAll) {
            const std::uint32_t packed = constantPacked_[i];
            if (live == 0xFFu) {
                const std::uint32_t eight[8] = {packed, packed, packed, packed, packed, packed, packed, packed};
                std::memcpy(row, eight, sizeof eight);
            } else {
                for (std::uint32_t bits = live; bits; bits &= bits - 1)
                    std::memcpy(row + 4 * __builtin_ctz(bits), &packed, 4);
            }
        } else if (useLut_[i]) {
            const auto& lut = tBlendLuts[i].bytes;
            auto at = [](const std::byte* p, int c) { return std::to_integer<std::uint8_t>(p[c]); };
            if (mask == WriteAll) {
                for (std::uint32_t bits = live; bits; bits &= bits - 1) {
                    std::byte* p = row + 4 * __builtin_ctz(bits);
                    const std::byte out[4] = {lut[0][at(p, 0)], lut[1][at(p, 1)], lut[2][at(p, 2)], lut[3][at(p, 3)]};
                    std::memcpy(p, out, 4);
                }
            } else {
                for (std::uint32_t bits = live; bits; bits &= bits - 1) {
                    std::byte* p = row + 4 * __builtin_ctz(bits);
                    for (int c = 0; c < 4; ++c)
                        if (mask & (1u << c)) p[c] = lut[c][at(p, c)];
                }
            }
        } else {
            for (std::uint32_t bits = live; bits; bits &= bits - 1)
                writeColor(i, row + std::size_t(target.pixelBytes) * __builtin_ctz(bits), constantColor_, mask);
        }
    }
}

}  // namespace
}  // namespace raster
}  // namespace engine::render::soft
