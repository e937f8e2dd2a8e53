// SPDX-License-Identifier: MIT
#pragma once
// The tile rasterizer for one program type (program-authoring header): coverage per 8x8
// block, early depth, the program's shade(), alpha test with the GS fail modes,
// alpha-to-coverage and blending, in submission order within a tile. A program opts into
// the fast paths by what it offers (see kernel/programs.hpp); a module instantiates this
// template for its own program in its own translation unit (kernel/program_kernel.hpp), so
// no virtual call happens per fragment.
#include <algorithm>
#include <array>
#include <concepts>
#include <cstring>
#include <type_traits>

#include "engine/render/soft/kernel/programs.hpp"
#include "engine/render/soft/kernel/raster_support.hpp"

namespace engine::render::soft {

struct TileCounters {
    std::uint64_t pixelsShaded = 0;
    std::uint64_t pixelsTouched = 0;
};

namespace raster {
namespace {  // as raster_support.hpp's

// Whether a full-screen program is a mask composite drawn over the frame with the
// SRC_ALPHA / INV_SRC_ALPHA blend, whose shade() is (compositeColor() at the pixel with
// non-finite components as 0, compositeFactor(x, y) in [0, 1]) ([Hathaway 2010] §3.5.4):
// then an 8-bit target takes compositeRow, which blends from the bytes directly.
template <typename Program>
constexpr bool hasCompositeHooks() {
    return requires(const Program& p) {
        { p.compositeColor() } -> std::same_as<const SoftTexture*>;
        { p.compositeFactor(0, 0) } -> std::same_as<float>;
    };
}

// Whether the program's shade() reads textures at the fragment's pixel (program_kernel.hpp).
template <typename Program>
constexpr bool readsPixels() {
    if constexpr (requires { Program::kReadsPixels; }) return Program::kReadsPixels;
    else return false;
}

template <typename Program>
class TriangleRasterizer {
public:
    TriangleRasterizer(const DrawState& draw, const Program& program, TileCounters& counters)
        : draw_(draw), program_(program), counters_(counters), pattern_(*draw.pattern),
          allSamples_((1u << draw.samples) - 1u) {
        if (draw.samples != 1) return;
        single_ = true;
        width_ = draw.depthTarget ? draw.depthTarget->desc.width
                                  : (draw.colorTargetCount ? draw.colorTargets[0]->desc.width : 0);
        if (draw.depthTest) {
            depth_ = view(*draw.depthTarget, false);
            // Depth-only draws store z as part of the row test.
            depthRowWrites_ = !draw.shade && draw.depthWrite;
            depthRow_ = depthRowWrites_ ? depthRowFunction<true>(draw.depthFunc) : depthRowFunction<false>(draw.depthFunc);
            if (depthRowWrites_) depthOnlyBlock_ = depthOnlyBlockFunction(draw.depthFunc);
        }
        for (int i = 0; i < draw.colorTargetCount; ++i) {
            TargetView& v = color_[i];
            v = view(*draw.colorTargets[i], draw.blendNeeded[i]);
            v.rgba8Plain = v.format == Format::RGBA8_UNORM && !v.blend && draw.blend[i].writeMask == WriteAll;
            v.srgb8Plain = v.format == Format::RGBA8_SRGB && !v.blend && draw.blend[i].writeMask == WriteAll;
            v.byteLut = (v.format == Format::RGBA8_UNORM || v.format == Format::RGBA8_SRGB) && v.blend &&
                        blendIsPerChannel(draw.blend[i]);
        }
        if constexpr (hasCompositeHooks<Program>()) {
            // A mask composite (SSAM's, SSAM+'s) as they are drawn: onto an 8-bit target,
            // with masks of any format (compositeRow); anything else takes the general path.
            compositeRow_ = !draw.capture && draw.shade && !draw.alphaTest.enabled && !draw.depthWrite &&
                            draw.colorTargetCount == 1 && isRgba8(draw.colorTargets[0]) && draw.blendNeeded[0] &&
                            isAlphaOverKeepingAlpha(draw.blend[0]) && isRgba8(program.compositeColor());
        }
#if SOFT_RASTER_SSE2
        if constexpr (std::is_same_v<Program, MaskedLitProgram>)
            alphaFirst_ = !draw.capture && draw.shade && draw.alphaTest.enabled &&
                          draw.alphaTest.failMode == AlphaFailMode::Keep && program.hasAlpha4();
        if constexpr (std::is_same_v<Program, AlphaOnlyProgram>) {
            // The mask path (shadeAlphaRow) covers what the mask pass is: no capture, no alpha
            // test, no depth write. Anything else takes the general path.
            alphaRow_ = !draw.capture && draw.shade && !draw.alphaTest.enabled && !draw.depthWrite;
            alphaZeroSkips_ = draw.colorTargetCount > 0;
            halfRow_ = draw.colorTargetCount > 0;
            for (int i = 0; i < draw.colorTargetCount; ++i) {
                oneOneBytes_[i] =
                    color_[i].format == Format::RGBA8_UNORM && color_[i].blend && isOneOneAddMax(draw.blend[i]);
                oneOneHalf_[i] = isHalfFloat(color_[i].format) && color_[i].blend && isOneOneAddMax(draw.blend[i]);
                alphaZeroSkips_ = alphaZeroSkips_ && oneOneBytes_[i];
                halfRow_ = halfRow_ && oneOneHalf_[i];
                for (int c = 0; c < 4; ++c)
                    if (!(draw.blend[i].writeMask & (1u << c))) unwrittenBytes_[i] |= 0xFFu << (8 * c);
            }
        }
#endif
    }

    void rasterize(const SetupTriangle& t, const Rect& tile) {
        const int x0 = std::max(tile.x, t.minX), x1 = std::min(tile.x + tile.width - 1, t.maxX);
        const int y0 = std::max(tile.y, t.minY), y1 = std::min(tile.y + tile.height - 1, t.maxY);
        if (x0 > x1 || y0 > y1) return;
        if (single_) {
            // Worked out at the first pixel that passes coverage and depth (shadeRow).
            constantPending_ = true;
            boxPixels_ = (x1 - x0 + 1) * (y1 - y0 + 1);
            rasterizeSingle(t, x0, y0, x1, y1);
            return;
        }
        // Blocks are aligned to the 8x8 grid, so a tile's blocks never straddle tiles.
        for (int by = y0 & ~(kBlockSize - 1); by <= y1; by += kBlockSize) {
            for (int bx = x0 & ~(kBlockSize - 1); bx <= x1; bx += kBlockSize) {
                const int px0 = std::max(bx, x0), px1 = std::min(bx + kBlockSize - 1, x1);
                const int py0 = std::max(by, y0), py1 = std::min(by + kBlockSize - 1, y1);
                rasterizeBlock(t, px0, py0, px1, py1);
            }
        }
    }

private:
    static TargetView view(SoftTexture& texture, bool blend) {
        TargetView v;
        v.base = texture.levels[0].texels.data();
        v.pixelBytes = texture.bytesPerSample;
        v.rowBytes = std::size_t(texture.levels[0].width) * texture.bytesPerSample;
        v.format = texture.desc.format;
        v.blend = blend;
        v.normalized = formatInfo(v.format).isNormalized();
        return v;
    }

    // A plane whose slopes are zero evaluates to exactly its value at every pixel centre
    // (value + (+-0) + (+-0) == value for finite pixel offsets), unless the value is -0.0,
    // which would come out +0.0.
    static bool constantPlane(const Plane& p) {
        return p.dx == 0.0f && p.dy == 0.0f && !(p.value == 0.0f && std::signbit(p.value));
    }

    // When every plane the program reads is constant, the fragment and so the shaded colour
    // are the same at every pixel (programs are pure functions of the fragment; Composite
    // reads textures by pixel position and is excluded): the program runs once per
    // triangle, and the alpha test and the stored bytes are worked out once.
    void prepareConstant(const SetupTriangle& t, int boxPixels) {
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
        bool writeRgb = true, writeAlpha = true;
        constantDepthWrite_ = draw_.depthWrite;
        constantDiscard_ = false;
        if (!draw_.alphaTest.passes(color.a)) {
            switch (draw_.alphaTest.failMode) {
                case AlphaFailMode::Keep: constantDiscard_ = true; break;
                case AlphaFailMode::FbOnly: constantDepthWrite_ = false; break;
                case AlphaFailMode::ZbOnly: writeRgb = writeAlpha = false; break;
                case AlphaFailMode::RgbOnly: writeAlpha = constantDepthWrite_ = false; break;
            }
        }
        const std::uint8_t allowed = std::uint8_t((writeRgb ? WriteRGB : 0) | (writeAlpha ? WriteA : 0));
        for (int i = 0; i < draw_.colorTargetCount; ++i) {
            const TargetView& target = color_[i];
            constantMask_[i] = draw_.blend[i].writeMask & allowed;
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
    void buildBlendLut(int i, const glm::vec4& color) {
        const TargetView& target = color_[i];
        BlendLut& lut = tBlendLuts[i];
        lut.valid = true;
        lut.blend = draw_.blend[i];
        lut.constant = draw_.blendConstant;
        lut.format = target.format;
        lut.color = color;
        for (int k = 0; k < 256; ++k) {
            std::byte dst[4] = {std::byte(k), std::byte(k), std::byte(k), std::byte(k)};
            const glm::vec4 out = blend(draw_.blend[i], color, loadTexel(dst, target.format), draw_.blendConstant,
                                        target.normalized);
            storeTexel(dst, target.format, out, 0xF);
            for (int c = 0; c < 4; ++c) lut.bytes[c][k] = dst[c];
        }
    }

    // Writes of the constant-colour fragment at the `live` pixels of a block row (bit i:
    // pixel bx + i), which passed coverage and depth; target by target, as the per-pixel
    // path does (each pixel's bytes depend only on that pixel).
    void writeConstantRow(int bx, int py, std::uint32_t live, const float* z, std::byte* depthAt) {
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

    void writeColor(int i, std::byte* p, const glm::vec4& color, std::uint8_t mask) {
        const TargetView& target = color_[i];
        if (!target.blend) {
            if (target.rgba8Plain && mask == WriteAll) storeRgba8Unorm(p, color);
            else if (target.srgb8Plain && mask == WriteAll) storeRgba8Srgb(p, color);
            else storeTexel(p, target.format, color, mask);
        } else {
            storeTexel(p, target.format,
                       blend(draw_.blend[i], color, loadTexel(p, target.format), draw_.blendConstant, target.normalized),
                       mask);
        }
    }

    // Single-sampled targets: the same block test as rasterizeBlock, then whole block rows
    // at a time; a partial block's coverage comes from the edge functions stepped exactly
    // in integers from pixel to pixel (E(x + 1) = E(x) + a * kPixelStep).
    void rasterizeSingle(const SetupTriangle& t, int x0, int y0, int x1, int y1) {
        for (int by = y0 & ~(kBlockSize - 1); by <= y1; by += kBlockSize) {
            const int py0 = std::max(by, y0), py1 = std::min(by + kBlockSize - 1, y1);
            for (int bx = x0 & ~(kBlockSize - 1); bx <= x1; bx += kBlockSize) {
                const int px0 = std::max(bx, x0), px1 = std::min(bx + kBlockSize - 1, x1);
                const std::int64_t xs0 = std::int64_t(px0) * kPixelStep, xs1 = std::int64_t(px1 + 1) * kPixelStep;
                const std::int64_t ys0 = std::int64_t(py0) * kPixelStep, ys1 = std::int64_t(py1 + 1) * kPixelStep;
                bool full = true, reject = false;
                for (int i = 0; i < 3; ++i) {
                    const std::int64_t maxE =
                        t.c[i] + t.a[i] * (t.a[i] > 0 ? xs1 : xs0) + t.b[i] * (t.b[i] > 0 ? ys1 : ys0);
                    const std::int64_t minE =
                        t.c[i] + t.a[i] * (t.a[i] > 0 ? xs0 : xs1) + t.b[i] * (t.b[i] > 0 ? ys0 : ys1);
                    reject = reject || maxE < 0;
                    full = full && minE >= 0;
                }
                if (reject) continue;
                const int n = px1 - px0 + 1, shift = px0 - bx;  // mask bit i: pixel bx + i
                if (full) {
                    const std::uint32_t rowMask = ((1u << n) - 1u) << shift;
                    if (depthOnlyBlock_ && bx + kBlockSize <= width_) {
                        counters_.pixelsTouched += depthOnlyBlock_(t, float(bx) + 0.5f, py0, py1, rowMask,
                                                                   depth_.at(bx, py0), depth_.rowBytes);
                        continue;
                    }
                    if (!draw_.depthTest && draw_.shade) {  // every pixel of the block is live
                        if (constantPending_) {
                            constantPending_ = false;
                            prepareConstant(t, boxPixels_);
                        }
                        if (constant_) {
                            const std::uint64_t pixels = std::uint64_t(kBitCount[rowMask]) * (py1 - py0 + 1);
                            counters_.pixelsTouched += pixels;
                            counters_.pixelsShaded += pixels;
                            if (!constantDiscard_)
                                for (int py = py0; py <= py1; ++py) writeConstantRow(bx, py, rowMask, nullptr, nullptr);
                            continue;
                        }
                    }
                    for (int py = py0; py <= py1; ++py) shadeRow(t, bx, py, rowMask);
                    continue;
                }
                std::int64_t e[3], step[3];
                const std::int64_t x = xs0 + kHalfPixel;
                for (int i = 0; i < 3; ++i) {
                    e[i] = t.a[i] * x + t.b[i] * (ys0 + kHalfPixel) + t.c[i];
                    step[i] = t.a[i] * kPixelStep;
                }
                for (int py = py0; py <= py1; ++py) {
                    std::uint32_t mask = 0;
                    std::int64_t e0 = e[0], e1 = e[1], e2 = e[2];
                    for (int i = 0; i < n; ++i) {
                        mask |= std::uint32_t((e0 | e1 | e2) >= 0) << i;
                        e0 += step[0], e1 += step[1], e2 += step[2];
                    }
                    if (mask) shadeRow(t, bx, py, mask << shift);
                    for (int i = 0; i < 3; ++i) e[i] += t.b[i] * kPixelStep;
                }
            }
        }
    }

    // Row py of the block at bx: `mask` the covered pixels (bit i: pixel bx + i).
    void shadeRow(const SetupTriangle& t, int bx, int py, std::uint32_t mask) {
        const float fy = float(py) + 0.5f - t.originY;
        const float centerX0 = float(bx) + 0.5f;
        alignas(16) float z[kBlockSize];
        std::uint32_t live = mask;
        std::byte* depthAt = nullptr;
        if (draw_.depthTest) {
            depthAt = depth_.at(bx, py);
            if (bx + kBlockSize <= width_) {  // all 8 lanes are in the row (and in this tile)
                live = depthRow_(t.depth, centerX0, t.originX, fy, mask, depthAt, z);
            } else {  // the block at the right edge of the target: 8 lanes of scratch
                const int lanes = width_ - bx;
                alignas(16) std::byte scratch[kBlockSize * sizeof(float)] = {};
                std::memcpy(scratch, depthAt, std::size_t(lanes) * sizeof(float));
                live = depthRow_(t.depth, centerX0, t.originX, fy, mask, scratch, z);
                if (depthRowWrites_ && live) std::memcpy(depthAt, scratch, std::size_t(lanes) * sizeof(float));
            }
            if (!live) return;
        }
        counters_.pixelsTouched += kBitCount[live];
        if (!draw_.shade) return;  // depth-only: no colour, no alpha test; depthRow_ stored z
        if (constantPending_) {
            constantPending_ = false;
            prepareConstant(t, boxPixels_);
        }

        if (constant_) {
            counters_.pixelsShaded += kBitCount[live];
            if (!constantDiscard_) writeConstantRow(bx, py, live, z, depthAt);
            return;
        }
        if constexpr (hasCompositeHooks<Program>()) {
            if (compositeRow_) {
                const Program& program = program_;
                compositeRow(bx, py, live, [&program](int x, int y) { return program.compositeFactor(x, y); });
                return;
            }
        }
#if SOFT_RASTER_SSE2
        if constexpr (std::is_same_v<Program, AlphaOnlyProgram>) {
            if (alphaRow_) {
                shadeAlphaRow(t, bx, py, live, centerX0, fy);
                return;
            }
        }
        if constexpr (std::is_same_v<Program, MaskedLitProgram>) {
            if (alphaFirst_) {
                shadeAlphaTestedRow(t, bx, py, live, centerX0, fy, z, depthAt);
                return;
            }
        }
        if (kBitCount[live] >= 2) {  // the attributes of 4 lanes at a time
            interpolateRow(t, centerX0, fy, live);
            for (std::uint32_t bits = live; bits; bits &= bits - 1) {
                const int i = __builtin_ctz(bits);
                shadeSingle(rowFragment(t, bx + i, py, i), bx + i, py, z[i], depthAt + i * sizeof(float));
            }
            return;
        }
#endif
        for (std::uint32_t bits = live; bits; bits &= bits - 1) {
            const int i = __builtin_ctz(bits);
            const int px = bx + i;
            shadeSingle(interpolate(t, px, py, float(px) + 0.5f - t.originX, fy), px, py, z[i],
                        depthAt + i * sizeof(float));
        }
    }

    // The composite programs' row (compositeRow_): shade() and the composite blend, per live
    // pixel the same operations, with the 8-bit texels decoded straight from the tables;
    // factorAt(px, py) is the program's alpha, in [0, 1] (both programs clamp it). The
    // foliage colour is finite (8-bit), so shade()'s non-finite check changes nothing; every
    // value is in [0, 1], so blend()'s clamps change nothing, and the alpha written is the
    // stored one (blend * 0 + d = d, encoded back to the same byte). Where the factor is 0
    // the colour is c * 0 + d * 1 = d, the decoded stored byte: nothing to write when bytes
    // round-trip (bytesRoundTrip), and most of the screen has no foliage.
    template <typename Factor>
    void compositeRow(int bx, int py, std::uint32_t live, const Factor& factorAt) {
        counters_.pixelsShaded += kBitCount[live];
        const ByteTables& tables = byteTables();
        const TargetView& target = color_[0];
        const bool srgbTarget = target.format == Format::RGBA8_SRGB;
        const float* targetTable = srgbTarget ? tables.srgb : tables.unorm;
        const SoftTexture& colorTexture = *program_.compositeColor();
        const float* colorTable = colorTexture.desc.format == Format::RGBA8_SRGB ? tables.srgb : tables.unorm;
        const bool skipZero = bytesRoundTrip();
        auto byteAt = [](const std::byte* p, int c) { return std::to_integer<std::uint8_t>(p[c]); };
        for (std::uint32_t bits = live; bits; bits &= bits - 1) {
            const int px = bx + __builtin_ctz(bits);
            const float blend = factorAt(px, py);
            if (blend == 0.0f && skipZero) continue;
            const std::byte* source = colorTexture.texel(0, px, py);
            std::byte* p = target.at(px, py);
            const float keep = 1.0f - blend;
            for (int c = 0; c < 3; ++c) {
                const float out = colorTable[byteAt(source, c)] * blend + targetTable[byteAt(p, c)] * keep;
                p[c] = std::byte{srgbTarget ? encodeSrgb8(out) : encodeUnorm8(out)};
            }
            if (!skipZero) p[3] = std::byte{encodeUnorm8(tables.unorm[byteAt(p, 3)])};
        }
    }

#if SOFT_RASTER_SSE2
    // AlphaOnly's row (alphaRow_): what shadeSingle does for each live lane, with the
    // program's replicated alpha kept as one float and ONE/ONE ADD/MAX RGBA8 blends done on
    // the stored bytes (blendOneOneRgba8, four pixels at a time where the row lies inside
    // the target: blendOneOneRgba8x4). Under such blends a pixel whose written bytes are
    // all 255 can no longer change: MAX gives max(encode(a), 255) = 255 and ADD
    // encode(a + 1) = 255 for any a in [0, 1], so the layers drawn after the mask saturated
    // there skip the sampling. (Still counted as shaded: the program's result is known
    // without running it.) ONE/ONE ADD/MAX blends onto half-float targets (the float masks)
    // are done on the stored halves in the same way (blendOneOneHalf, one_one_half_blend.hpp;
    // four pixels at a time: shadeAlphaRowHalf4).
    void shadeAlphaRow(const SetupTriangle& t, int bx, int py, std::uint32_t live, float centerX0, float fy) {
        counters_.pixelsShaded += kBitCount[live];
        const bool four = program_.hasAlpha4();
        if (four && alphaZeroSkips_ && bx + kBlockSize <= width_) {
            shadeAlphaRow4(t, bx, py, live, centerX0, fy);
            return;
        }
        if (four && halfRow_) {
            shadeAlphaRowHalf4(t, bx, py, live, centerX0, fy);
            return;
        }
        if (alphaZeroSkips_) {
            std::uint32_t open = 0;
            for (std::uint32_t bits = live; bits; bits &= bits - 1) {
                const int i = __builtin_ctz(bits);
                for (int k = 0; k < draw_.colorTargetCount; ++k) {
                    std::uint32_t stored;
                    std::memcpy(&stored, color_[k].at(bx + i, py), sizeof stored);
                    if ((stored | unwrittenBytes_[k]) != 0xFFFFFFFFu) {  // not saturated
                        open |= 1u << i;
                        break;
                    }
                }
            }
            live = open;
            if (!live) return;
        }
        interpolateRow(t, centerX0, fy, live);
        alignas(16) float alpha[kBlockSize];
        if (four) {
            for (int h = 0; h < 2; ++h) {
                const std::uint32_t lanes = (live >> (4 * h)) & 0xFu;
                if (lanes) _mm_store_ps(alpha + 4 * h, alpha4(h, lanes));
            }
        }
        for (std::uint32_t bits = live; bits; bits &= bits - 1) {
            const int i = __builtin_ctz(bits), px = bx + i;
            const float a = four ? alpha[i] : program_.alpha(rowFragment(t, px, py, i));
            // MAX with 0 and ADD of 0 store back the byte that was there (blendOneOneRgba8:
            // max(0, d) = d, encode(0 + d / 255) = d), so a zero alpha changes nothing.
            if (alphaZeroSkips_ && a == 0.0f) continue;
            for (int k = 0; k < draw_.colorTargetCount; ++k) {
                const std::uint8_t mask = draw_.blend[k].writeMask;
                if (!mask) continue;
                std::byte* p = color_[k].at(px, py);
                if (oneOneBytes_[k]) blendOneOneRgba8(draw_.blend[k], p, a, mask);
                else if (oneOneHalf_[k]) blendOneOneHalf(draw_.blend[k], p, color_[k].pixelBytes / 2, a, mask);
                else writeColor(k, p, glm::vec4(a), mask);
            }
        }
    }

    // shadeAlphaRow where every target takes blendOneOneRgba8 and the 8 pixels lie inside
    // the targets: four lanes at a time, branch-free per lane.
    void shadeAlphaRow4(const SetupTriangle& t, int bx, int py, std::uint32_t live, float centerX0, float fy) {
        for (int h = 0; h < 2; ++h) {
            std::uint32_t lanes = (live >> (4 * h)) & 0xFu;
            if (!lanes) continue;
            std::uint32_t saturated = 0xFu;  // in every target (see shadeAlphaRow)
            for (int k = 0; k < draw_.colorTargetCount; ++k)
                saturated &= saturatedLanes(color_[k].at(bx + 4 * h, py), unwrittenBytes_[k]);
            lanes &= ~saturated;
            if (!lanes) continue;
            interpolateHalf(t, centerX0, fy, h);
            // A zero alpha needs no skipping: it stores back the bytes that were there.
            const __m128 a = alpha4(h, lanes);
            for (int k = 0; k < draw_.colorTargetCount; ++k)
                blendOneOneRgba8x4(draw_.blend[k], color_[k].at(bx + 4 * h, py), a, lanes);
        }
    }

    // shadeAlphaRow where every target is a half-float one that blendOneOneHalf4 applies to
    // (SSAM's float masks): four lanes at a time. No lane is skipped: a float ADD mask never
    // saturates, and a zero alpha can still change the stored bits (MAX of 0 over -0 or
    // NaN gives +0; 0 + -0 = +0).
    void shadeAlphaRowHalf4(const SetupTriangle& t, int bx, int py, std::uint32_t live, float centerX0, float fy) {
        for (int h = 0; h < 2; ++h) {
            const std::uint32_t lanes = (live >> (4 * h)) & 0xFu;
            if (!lanes) continue;
            interpolateHalf(t, centerX0, fy, h);
            const __m128 a = alpha4(h, lanes);
            const bool inside = bx + 4 * h + 4 <= width_;  // all four pixels: whole 8-byte R16F loads
            for (int k = 0; k < draw_.colorTargetCount; ++k) {
                const std::uint8_t mask = draw_.blend[k].writeMask;
                std::byte* p = color_[k].at(bx + 4 * h, py);
                const int channels = color_[k].pixelBytes / 2;
                if (channels == 1 && inside && (mask & 1u)) blendOneOneR16f4(draw_.blend[k], p, a, lanes);
                else if (channels == 4 && mask) blendOneOneRgba16f4(draw_.blend[k], p, a, lanes, mask);
                else if (mask) blendOneOneHalf4(draw_.blend[k], p, channels, a, lanes, mask);
            }
        }
    }

    // program_.alpha4 of lanes 4h..4h+3 of row_.
    __m128 alpha4(int h, std::uint32_t lanes) const {
        const int o = 4 * h;
        const float* duv[4] = {row_.duv[0] + o, row_.duv[1] + o, row_.duv[2] + o, row_.duv[3] + o};
        return program_.alpha4(row_.color[3] + o, row_.uv[0] + o, row_.uv[1] + o, duv, lanes);
    }

    // MaskedLit's row under a Keep alpha test (alphaFirst_): the texel alpha four lanes
    // at a time (the general sampler's bits), then the alpha test on the alpha shade()
    // would output, (baseColorFactor.a * vertex alpha) * texel alpha (toStraight keeps
    // alpha), and the texel's colour and shade() for the fragments that pass only: a
    // discarded fragment writes nothing, so neither is ever needed.
    void shadeAlphaTestedRow(const SetupTriangle& t, int bx, int py, std::uint32_t live, float centerX0, float fy,
                             const float* z, std::byte* depthAt) {
        interpolateRow(t, centerX0, fy, live);
        if (!program_.texture) {  // alpha4 without a texture: factor * vertex alpha
            alignas(16) float alpha[kBlockSize];
            std::uint32_t passing = 0;
            for (int h = 0; h < 2; ++h) {
                const std::uint32_t lanes = (live >> (4 * h)) & 0xFu;
                if (lanes) _mm_store_ps(alpha + 4 * h, alpha4(h, lanes));
            }
            for (std::uint32_t bits = live; bits; bits &= bits - 1) {
                const int i = __builtin_ctz(bits);
                if (draw_.alphaTest.passes(alpha[i])) passing |= 1u << i;
            }
            counters_.pixelsShaded += kBitCount[live & ~passing];  // shaded as far as their alpha
            for (std::uint32_t bits = passing; bits; bits &= bits - 1) {
                const int i = __builtin_ctz(bits);
                shadeSingle(rowFragment(t, bx + i, py, i), bx + i, py, z[i], depthAt + i * sizeof(float));
            }
            return;
        }
        const AlphaSampler& sampler = program_.alphaSampler;
        const float factorAlpha = program_.params.baseColorFactor.a;
        for (int h = 0; h < 2; ++h) {
            const std::uint32_t lanes = (live >> (4 * h)) & 0xFu;
            if (!lanes) continue;
            const int o = 4 * h;
            const AlphaSampler::Lookup4 lookup = sampler.lookup4(row_.uv[0] + o, row_.uv[1] + o, row_.duv[0] + o,
                                                                 row_.duv[1] + o, row_.duv[2] + o, row_.duv[3] + o, lanes);
            alignas(16) float texelAlpha[4];
            _mm_store_ps(texelAlpha, sampler.alpha4(lookup));
            std::uint32_t passing = 0;
            for (std::uint32_t bits = lanes; bits; bits &= bits - 1) {
                const int k = __builtin_ctz(bits);
                if (draw_.alphaTest.passes(factorAlpha * row_.color[3][o + k] * texelAlpha[k])) passing |= 1u << k;
            }
            counters_.pixelsShaded += kBitCount[lanes & ~passing];  // shaded as far as their alpha
            if (!passing) continue;
            alignas(16) float texels[4][4];
            sampler.rgba4(lookup, passing, texels);
            for (std::uint32_t bits = passing; bits; bits &= bits - 1) {
                const int k = __builtin_ctz(bits), i = o + k;
                const glm::vec4 texel(texels[k][0], texels[k][1], texels[k][2], texels[k][3]);
                writeShaded(program_.shadeSampled(rowFragment(t, bx + i, py, i), texel), bx + i, py, z[i],
                            depthAt + i * sizeof(float));
            }
        }
    }

    // interpolate() for the lanes of a block row (pixel bx + i in lane i) in the halves of the
    // row that hold a lane of `lanes`, lane by lane the same IEEE operations in the same
    // order (the division included), into row_.
    void interpolateRow(const SetupTriangle& t, float centerX0, float fy, std::uint32_t lanes) {
        for (int h = 0; h < 2; ++h)
            if ((lanes >> (4 * h)) & 0xFu) interpolateHalf(t, centerX0, fy, h);
    }
    void interpolateHalf(const SetupTriangle& t, float centerX0, float fy, int h) {
        constexpr ProgramNeeds needs = Program::kNeeds;
        if constexpr (needs.anyAttribute()) {
            const __m128 fx = _mm_sub_ps(
                _mm_add_ps(_mm_set1_ps(centerX0),
                           _mm_setr_ps(float(4 * h), float(4 * h + 1), float(4 * h + 2), float(4 * h + 3))),
                _mm_set1_ps(t.originX));
            auto evaluateLanes = [&](const Plane& p) {
                return _mm_add_ps(_mm_add_ps(_mm_set1_ps(p.value), _mm_mul_ps(_mm_set1_ps(p.dx), fx)),
                                  _mm_set1_ps(p.dy * fy));
            };
            const __m128 w = _mm_div_ps(_mm_set1_ps(1.0f), evaluateLanes(t.inverseW));
            _mm_store_ps(row_.w + 4 * h, w);
            auto attribute = [&](int k) { return _mm_mul_ps(evaluateLanes(t.attributeOverW[k]), w); };
            if constexpr (needs.uv) {
                const __m128 u = attribute(kAttrU), v = attribute(kAttrV);
                _mm_store_ps(row_.uv[0] + 4 * h, u);
                _mm_store_ps(row_.uv[1] + 4 * h, v);
                if constexpr (needs.derivatives) {
                    const Plane& pu = t.attributeOverW[kAttrU];
                    const Plane& pv = t.attributeOverW[kAttrV];
                    auto derivative = [&](float slope, __m128 value, float inverseWSlope) {
                        return _mm_mul_ps(_mm_sub_ps(_mm_set1_ps(slope), _mm_mul_ps(value, _mm_set1_ps(inverseWSlope))), w);
                    };
                    _mm_store_ps(row_.duv[0] + 4 * h, derivative(pu.dx, u, t.inverseW.dx));
                    _mm_store_ps(row_.duv[1] + 4 * h, derivative(pv.dx, v, t.inverseW.dx));
                    _mm_store_ps(row_.duv[2] + 4 * h, derivative(pu.dy, u, t.inverseW.dy));
                    _mm_store_ps(row_.duv[3] + 4 * h, derivative(pv.dy, v, t.inverseW.dy));
                }
            }
            if constexpr (needs.normal)
                for (int k = 0; k < 3; ++k) _mm_store_ps(row_.normal[k] + 4 * h, attribute(kAttrNormal + k));
            if constexpr (needs.color)
                for (int k = 0; k < 4; ++k) _mm_store_ps(row_.color[k] + 4 * h, attribute(kAttrColor + k));
            if constexpr (needs.colorAlpha) _mm_store_ps(row_.color[3] + 4 * h, attribute(kAttrColor + 3));
        }
    }

    // The fragment of lane i from row_ (what interpolate() gives for that pixel).
    Fragment rowFragment(const SetupTriangle& t, int px, int py, int i) const {
        constexpr ProgramNeeds needs = Program::kNeeds;
        Fragment f;
        f.x = px;
        f.y = py;
        f.frontFacing = t.frontFacing;
        if constexpr (needs.uv) {
            f.uv = {row_.uv[0][i], row_.uv[1][i]};
            if constexpr (needs.derivatives) {
                f.duv.dx = {row_.duv[0][i], row_.duv[1][i]};
                f.duv.dy = {row_.duv[2][i], row_.duv[3][i]};
            }
        }
        if constexpr (needs.normal) f.normal = {row_.normal[0][i], row_.normal[1][i], row_.normal[2][i]};
        if constexpr (needs.color) f.color = {row_.color[0][i], row_.color[1][i], row_.color[2][i], row_.color[3][i]};
        if constexpr (needs.colorAlpha) f.color.a = row_.color[3][i];
        if constexpr (needs.anyAttribute()) f.clipW = row_.w[i];
        return f;
    }
#endif

    // One covered (and depth-passing) pixel of a single-sampled target.
    void shadeSingle(const Fragment& fragment, int px, int py, float z, std::byte* depthAt) {
        writeShaded(program_.shade(fragment), px, py, z, depthAt);
    }
    // What shadeSingle does with the shaded colour.
    void writeShaded(const glm::vec4& color, int px, int py, float z, std::byte* depthAt) {
        ++counters_.pixelsShaded;
        if (draw_.capture) {
            if (draw_.alphaTest.passes(color.a)) draw_.capture->add(px, py, {z, color});
            return;
        }

        bool writeRgb = true, writeAlpha = true, writeDepth = draw_.depthWrite;
        if (!draw_.alphaTest.passes(color.a)) {
            switch (draw_.alphaTest.failMode) {
                case AlphaFailMode::Keep: return;
                case AlphaFailMode::FbOnly: writeDepth = false; break;
                case AlphaFailMode::ZbOnly: writeRgb = writeAlpha = false; break;
                case AlphaFailMode::RgbOnly: writeAlpha = writeDepth = false; break;
            }
        }
        if (writeDepth) std::memcpy(depthAt, &z, sizeof z);
        const std::uint8_t allowed = std::uint8_t((writeRgb ? WriteRGB : 0) | (writeAlpha ? WriteA : 0));
        for (int i = 0; i < draw_.colorTargetCount; ++i) {
            const std::uint8_t mask = draw_.blend[i].writeMask & allowed;
            if (mask) writeColor(i, color_[i].at(px, py), color, mask);
        }
    }

    // Trivial reject when one edge is negative over the whole block, trivial accept when
    // all three are non-negative over it; the block's extent covers every sample position.
    void rasterizeBlock(const SetupTriangle& t, int px0, int py0, int px1, int py1) {
        const std::int64_t xs0 = std::int64_t(px0) * kPixelStep, xs1 = std::int64_t(px1 + 1) * kPixelStep;
        const std::int64_t ys0 = std::int64_t(py0) * kPixelStep, ys1 = std::int64_t(py1 + 1) * kPixelStep;
        bool full = true;
        for (int i = 0; i < 3; ++i) {
            const std::int64_t maxE = t.c[i] + t.a[i] * (t.a[i] > 0 ? xs1 : xs0) + t.b[i] * (t.b[i] > 0 ? ys1 : ys0);
            if (maxE < 0) return;
            const std::int64_t minE = t.c[i] + t.a[i] * (t.a[i] > 0 ? xs0 : xs1) + t.b[i] * (t.b[i] > 0 ? ys0 : ys1);
            full = full && minE >= 0;
        }
        if (full) {
            for (int py = py0; py <= py1; ++py)
                for (int px = px0; px <= px1; ++px) shadePixel(t, px, py, allSamples_);
            return;
        }
        for (int py = py0; py <= py1; ++py) {
            for (int px = px0; px <= px1; ++px) {
                const std::uint32_t coverage = sampleCoverage(t, px, py);
                if (coverage) shadePixel(t, px, py, coverage);
            }
        }
    }

    std::uint32_t sampleCoverage(const SetupTriangle& t, int px, int py) const {
        std::uint32_t mask = 0;
        for (int s = 0; s < pattern_.count; ++s) {
            const std::int64_t x = std::int64_t(px) * kPixelStep + kHalfPixel + pattern_.dx[s] * kSampleOffsetScale;
            const std::int64_t y = std::int64_t(py) * kPixelStep + kHalfPixel + pattern_.dy[s] * kSampleOffsetScale;
            bool inside = true;
            for (int i = 0; i < 3; ++i) inside = inside && (t.a[i] * x + t.b[i] * y + t.c[i] >= 0);
            mask |= std::uint32_t(inside) << s;
        }
        return mask;
    }

    void shadePixel(const SetupTriangle& t, int px, int py, std::uint32_t live) {
        const float fx = float(px) + 0.5f - t.originX, fy = float(py) + 0.5f - t.originY;
        std::array<float, 8> z{};
        if (draw_.depthTest) {
            for (int s = 0; s < pattern_.count; ++s) {
                if (!(live & (1u << s))) continue;
                const float sx = fx + pattern_.dx[s] / 16.0f, sy = fy + pattern_.dy[s] / 16.0f;
                z[s] = clamp01(evaluate(t.depth, sx, sy));
                if (!compare(draw_.depthFunc, z[s], loadDepth(draw_.depthTarget->sample(px, py, s))))
                    live &= ~(1u << s);
            }
            if (!live) return;
        }
        ++counters_.pixelsTouched;

        if (!draw_.shade) {  // depth-only: no colour is written and no alpha test applies
            if (draw_.depthWrite) storeDepth(px, py, live, z);
            return;
        }

        const glm::vec4 color = program_.shade(interpolate(t, px, py, fx, fy));
        ++counters_.pixelsShaded;

        if (draw_.alphaToCoverage && draw_.samples > 1) {
            // round(alpha * samples) samples covered, the first ones in sample order.
            const int covered = static_cast<int>(clamp01(color.a) * float(draw_.samples) + 0.5f);
            live &= (1u << covered) - 1u;
            if (!live) return;
        }

        // Alpha test in the GS sense ([PCSX2]): on failure the fail mode decides what
        // is still written.
        bool writeRgb = true, writeAlpha = true, writeDepth = draw_.depthWrite;
        if (!draw_.alphaTest.passes(color.a)) {
            switch (draw_.alphaTest.failMode) {
                case AlphaFailMode::Keep: return;
                case AlphaFailMode::FbOnly: writeDepth = false; break;
                case AlphaFailMode::ZbOnly: writeRgb = writeAlpha = false; break;
                case AlphaFailMode::RgbOnly: writeAlpha = writeDepth = false; break;
            }
        }
        if (writeDepth) storeDepth(px, py, live, z);
        const std::uint8_t allowed = std::uint8_t((writeRgb ? WriteRGB : 0) | (writeAlpha ? WriteA : 0));
        if (!allowed) return;
        for (int i = 0; i < draw_.colorTargetCount; ++i) {
            const std::uint8_t mask = draw_.blend[i].writeMask & allowed;
            if (!mask) continue;
            SoftTexture& target = *draw_.colorTargets[i];
            const Format format = target.desc.format;
            for (int s = 0; s < pattern_.count; ++s) {
                if (!(live & (1u << s))) continue;
                std::byte* p = target.sample(px, py, s);
                glm::vec4 out = color;
                if (draw_.blendNeeded[i])
                    out = blend(draw_.blend[i], color, loadTexel(p, format), draw_.blendConstant,
                                formatInfo(format).isNormalized());
                storeTexel(p, format, out, mask);
            }
        }
    }

    void storeDepth(int px, int py, std::uint32_t live, const std::array<float, 8>& z) {
        for (int s = 0; s < pattern_.count; ++s)
            if (live & (1u << s)) std::memcpy(draw_.depthTarget->sample(px, py, s), &z[s], sizeof(float));
    }

    // Perspective-correct attributes at the pixel centre: attribute/w and 1/w are linear
    // in screen space; UV derivatives come analytically from the same planes.
    Fragment interpolate(const SetupTriangle& t, int px, int py, float fx, float fy) const {
        constexpr ProgramNeeds needs = Program::kNeeds;
        Fragment f;
        f.x = px;
        f.y = py;
        f.frontFacing = t.frontFacing;
        if constexpr (needs.anyAttribute()) {
            const float inverseW = evaluate(t.inverseW, fx, fy);
            const float w = 1.0f / inverseW;
            f.clipW = w;
            auto attribute = [&](int k) { return evaluate(t.attributeOverW[k], fx, fy) * w; };
            if constexpr (needs.uv) {
                f.uv = {attribute(kAttrU), attribute(kAttrV)};
                if constexpr (needs.derivatives) {
                    const Plane& pu = t.attributeOverW[kAttrU];
                    const Plane& pv = t.attributeOverW[kAttrV];
                    f.duv.dx = {(pu.dx - f.uv.x * t.inverseW.dx) * w, (pv.dx - f.uv.y * t.inverseW.dx) * w};
                    f.duv.dy = {(pu.dy - f.uv.x * t.inverseW.dy) * w, (pv.dy - f.uv.y * t.inverseW.dy) * w};
                }
            }
            if constexpr (needs.normal)
                f.normal = {attribute(kAttrNormal), attribute(kAttrNormal + 1), attribute(kAttrNormal + 2)};
            if constexpr (needs.color)
                f.color = {attribute(kAttrColor), attribute(kAttrColor + 1), attribute(kAttrColor + 2),
                           attribute(kAttrColor + 3)};
            if constexpr (needs.colorAlpha) f.color.a = attribute(kAttrColor + 3);
        }
        return f;
    }

    const DrawState& draw_;
    const Program& program_;
    TileCounters& counters_;
    const SamplePattern& pattern_;
    const std::uint32_t allSamples_;
    bool single_ = false;  // one sample per pixel: the row-at-a-time path
    struct RowAttributes {  // interpolateRow's output: [component][lane]
        alignas(16) float uv[2][kBlockSize];
        alignas(16) float duv[4][kBlockSize];  // du/dx, dv/dx, du/dy, dv/dy
        alignas(16) float normal[3][kBlockSize];
        alignas(16) float color[4][kBlockSize];
        alignas(16) float w[kBlockSize];  // clip w (Fragment::clipW)
    } row_;
    int width_ = 0;        // of the pass's targets
    TargetView depth_;
    DepthRowFn depthRow_ = nullptr;
    DepthOnlyBlockFn depthOnlyBlock_ = nullptr;  // depth-only draws (test and write)
    bool depthRowWrites_ = false;
    std::array<TargetView, kMaxColorTargets> color_{};
    // The current triangle's constant fragment (prepareConstant), if it has one.
    bool constant_ = false;
    bool constantPending_ = false;  // prepareConstant not yet run for the current triangle
    int boxPixels_ = 0;             // the current triangle's box within the tile
    glm::vec4 constantColor_{0.0f};
    bool constantDiscard_ = false;
    bool constantDepthWrite_ = false;
    std::array<std::uint8_t, kMaxColorTargets> constantMask_{};
    std::array<std::uint32_t, kMaxColorTargets> constantPacked_{};
    std::array<bool, kMaxColorTargets> useLut_{};
    bool compositeRow_ = false;  // CompositeProgram, CoverageCompositeProgram: compositeRow
    bool alphaFirst_ = false;    // MaskedLit: alpha-test (Keep) on the alpha alone before shading
    // AlphaOnly's row path (shadeAlphaRow).
    bool alphaRow_ = false;
    bool alphaZeroSkips_ = false;                       // every target ignores a zero alpha
    std::array<bool, kMaxColorTargets> oneOneBytes_{};  // blendOneOneRgba8 applies
    std::array<bool, kMaxColorTargets> oneOneHalf_{};   // blendOneOneHalf applies
    bool halfRow_ = false;                              // every target: blendOneOneHalf4 (shadeAlphaRowHalf4)
    std::array<std::uint32_t, kMaxColorTargets> unwrittenBytes_{};  // 0xFF in each byte the write mask leaves
};


}  // namespace
}  // namespace raster
}  // namespace engine::render::soft
