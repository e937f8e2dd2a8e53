// SPDX-License-Identifier: MIT
#pragma once
// TriangleRasterizer's per-pixel stages after coverage: the depth test, shade(),
// alpha-to-coverage, the alpha test with the GS fail modes ([PCSX2]), blending and the writes;
// the row dispatch that picks a program's fast path; perspective-correct interpolation.
#include "engine/render/kernel/detail/rasterizer/rasterizer_class.hpp"

namespace engine::render::soft {
namespace raster {
namespace {  // as raster_support.hpp's

// Row py of the block at bx: `mask` the covered pixels (bit i: pixel bx + i).
template <typename Program>
inline void TriangleRasterizer<Program>::shadeRow(const SetupTriangle& t, int bx, int py, std::uint32_t mask) {
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
    if constexpr (hasRowShader<Program>()) {
        alignas(16) glm::vec4 colors[kBlockSize];
        program_.shadeRow(draw_.isa, bx, py, live, colors);
        std::uint32_t written = live;
        if (rowZeroSkips_) {
            for (std::uint32_t bits = live; bits; bits &= bits - 1)
                if (colors[__builtin_ctz(bits)] == glm::vec4(0.0f)) written &= ~(bits & -bits);
            counters_.pixelsShaded += kBitCount[live & ~written];
        }
        for (std::uint32_t bits = written; bits; bits &= bits - 1) {
            const int i = __builtin_ctz(bits);
            writeShaded(colors[i], bx + i, py, z[i], depthAt + i * sizeof(float));
        }
        return;
    }
#if SOFT_RASTER_SSE2
    if constexpr (hasReplicatedAlphaHooks<Program>()) {
        if (alphaRow_) {
            shadeAlphaRow(t, bx, py, live, centerX0, fy);
            return;
        }
    }
    if constexpr (hasAlphaFirstHooks<Program>()) {
        if (alphaFirst_) {
            shadeAlphaTestedRow(t, bx, py, live, centerX0, fy, z, depthAt);
            return;
        }
    }
    if constexpr (hasSampledRowHooks<Program>()) {
        if (sampledRow_) {
            shadeSampledRow(t, bx, py, live, centerX0, fy, z, depthAt);
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

// One covered (and depth-passing) pixel of a single-sampled target.
template <typename Program>
inline void TriangleRasterizer<Program>::shadeSingle(const Fragment& fragment, int px, int py, float z,
                                                     std::byte* depthAt) {
    writeShaded(program_.shade(fragment), px, py, z, depthAt);
}

// What shadeSingle does with the shaded colour.
template <typename Program>
inline void TriangleRasterizer<Program>::writeShaded(const glm::vec4& color, int px, int py, float z,
                                                     std::byte* depthAt) {
    ++counters_.pixelsShaded;
    if (draw_.capture) {
        if (draw_.alphaTest.passes(color.a)) draw_.capture->add(px, py, {z, color});
        return;
    }

    const AlphaTestWrites writes = alphaTestWrites(draw_.alphaTest, color.a, draw_.depthWrite);
    if (writes.discard) return;
    if (writes.depth) std::memcpy(depthAt, &z, sizeof z);
    for (int i = 0; i < draw_.colorTargetCount; ++i) {
        const std::uint8_t mask = draw_.blend[i].writeMask & writes.channels;
        if (mask) writeColor(i, color_[i].at(px, py), color, mask);
    }
}

template <typename Program>
inline void TriangleRasterizer<Program>::writeColor(int i, std::byte* p, const glm::vec4& color, std::uint8_t mask) {
    const TargetView& target = color_[i];
    if (!target.blend) {
        if (target.rgba8Plain && mask == WriteAll) storeRgba8Unorm(p, color);
        else if (target.srgb8Plain && mask == WriteAll) storeRgba8Srgb(p, color);
        else storeTexel(p, target.format, color, mask);
    } else {
        // Most of a composite layer is empty: (0, 0, 0, 0) blended there stores what is there.
        if (target.zeroKeeps && color == glm::vec4(0.0f)) return;
        storeTexel(p, target.format,
                   blend(draw_.blend[i], color, loadTexel(p, target.format), draw_.blendConstant, target.normalized),
                   mask);
    }
}

template <typename Program>
inline void TriangleRasterizer<Program>::shadePixel(const SetupTriangle& t, int px, int py, std::uint32_t live) {
    const float fx = float(px) + 0.5f - t.originX, fy = float(py) + 0.5f - t.originY;
    std::array<float, 8> z{};
    if (draw_.depthTest) {
        for (int s = 0; s < pattern_.count; ++s) {
            if (!(live & (1u << s))) continue;
            const float sx = fx + pattern_.dx[s] / 16.0f, sy = fy + pattern_.dy[s] / 16.0f;
            z[s] = clamp01(evaluate(t.depth, sx, sy));
            if (!compare(draw_.depthFunc, z[s], loadDepth(draw_.depthTarget->sample(px, py, s)))) live &= ~(1u << s);
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
        // clamp01 keeps it non-negative: + 0.5 and truncation round half up.
        const int covered =
            static_cast<int>(clamp01(color.a) * float(draw_.samples) + 0.5f);  // NOLINT(bugprone-incorrect-roundings)
        live &= (1u << covered) - 1u;
        if (!live) return;
    }

    // The alpha test in the GS sense ([PCSX2]): a failing fragment writes what its fail mode keeps.
    const AlphaTestWrites writes = alphaTestWrites(draw_.alphaTest, color.a, draw_.depthWrite);
    if (writes.discard) return;
    if (writes.depth) storeDepth(px, py, live, z);
    if (!writes.channels) return;
    for (int i = 0; i < draw_.colorTargetCount; ++i) {
        const std::uint8_t mask = draw_.blend[i].writeMask & writes.channels;
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

template <typename Program>
inline void TriangleRasterizer<Program>::storeDepth(int px, int py, std::uint32_t live, const std::array<float, 8>& z) {
    for (int s = 0; s < pattern_.count; ++s)
        if (live & (1u << s)) std::memcpy(draw_.depthTarget->sample(px, py, s), &z[s], sizeof(float));
}

// Perspective-correct attributes at the pixel centre: attribute/w and 1/w are linear
// in screen space; UV derivatives come analytically from the same planes.
template <typename Program>
inline Fragment TriangleRasterizer<Program>::interpolate(const SetupTriangle& t, int px, int py, float fx,
                                                         float fy) const {
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

}  // namespace
}  // namespace raster
}  // namespace engine::render::soft
