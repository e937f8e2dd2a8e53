// SPDX-License-Identifier: MIT
#pragma once
// TriangleRasterizer's row paths for programs that offer fast-path hooks (rasterizer_class.hpp):
// the mask composites' byte row, the replicated-alpha mask rows, the alpha-first row, and the
// SSE2 interpolation of a block row they share; each writes what the general path would, bit
// for bit.
#include "engine/render/kernel/detail/rasterizer/rasterizer_class.hpp"

namespace engine::render::soft {
namespace raster {
namespace {  // as raster_support.hpp's

// The composite programs' row (compositeRow_): shade() and the composite blend, per live
// pixel the same operations, with the 8-bit texels decoded straight from the tables (or the
// colours the program's compositeColorRow gives); factorAt(px, py) is the program's alpha, in
// [0, 1] (both programs clamp it), unless its compositeFactorRow gives the row's. The foliage
// colour is finite and in [0, 1] (8-bit, or the program's compositeColorRow, clamped as blend()
// would), so shade()'s non-finite check and blend()'s clamps change nothing, and the alpha
// written is the stored one (blend * 0 + d = d, encoded back to the same byte). Where the factor is 0 the colour is c * 0 + d * 1 = d, the
// decoded stored byte: nothing to write when bytes round-trip (bytesRoundTrip), and most of the
// screen has no foliage, so the colours are asked only for the pixels left.
template <typename Program>
template <typename Factor>
inline void TriangleRasterizer<Program>::compositeRow(int bx, int py, std::uint32_t live, const Factor& factorAt) {
    counters_.pixelsShaded += kBitCount[live];
    const ByteTables& tables = byteTables();
    const TargetView& target = color_[0];
    const bool srgbTarget = target.format == Format::RGBA8_SRGB;
    const float* targetTable = srgbTarget ? tables.srgb : tables.unorm;
    const SoftTexture& colorTexture = *program_.compositeColor();
    const float* colorTable = colorTexture.desc.format == Format::RGBA8_SRGB ? tables.srgb : tables.unorm;
    const bool skipZero = bytesRoundTrip();
    auto byteAt = [](const std::byte* p, int c) { return std::to_integer<std::uint8_t>(p[c]); };
    float blends[kBlockSize];
    bool wholeRow = false;  // the program's compositeFactorRow gave every lane's factor
    if constexpr (hasCompositeFactorRow<Program>())
        wholeRow = bx + kBlockSize <= width_ && program_.compositeFactorRow(bx, py, blends);
    std::uint32_t drawn = 0;
    for (std::uint32_t bits = live; bits; bits &= bits - 1) {
        const int i = __builtin_ctz(bits);
        if (!wholeRow) blends[i] = factorAt(bx + i, py);
        if (blends[i] != 0.0f || !skipZero) drawn |= 1u << i;
    }
    glm::vec3 ownColors[kBlockSize];
    bool own = false;
    if constexpr (hasCompositeColorRow<Program>())
        own = drawn != 0 && program_.compositeColorRow(bx, py, drawn, ownColors);
    for (std::uint32_t bits = drawn; bits; bits &= bits - 1) {
        const int i = __builtin_ctz(bits), px = bx + i;
        const float blend = blends[i];
        const std::byte* source = colorTexture.texel(0, px, py);
        std::byte* p = target.at(px, py);
        const float keep = 1.0f - blend;
        for (int c = 0; c < 3; ++c) {
            const float color = own ? ownColors[i][c] : colorTable[byteAt(source, c)];
            const float out = color * blend + targetTable[byteAt(p, c)] * keep;
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
template <typename Program>
inline void TriangleRasterizer<Program>::shadeAlphaRow(const SetupTriangle& t, int bx, int py, std::uint32_t live,
                                                       float centerX0, float fy) {
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
template <typename Program>
inline void TriangleRasterizer<Program>::shadeAlphaRow4(const SetupTriangle& t, int bx, int py, std::uint32_t live,
                                                        float centerX0, float fy) {
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
// (float coverage masks): four lanes at a time. No lane is skipped: a float ADD mask never
// saturates, and a zero alpha can still change the stored bits (MAX of 0 over -0 or
// NaN gives +0; 0 + -0 = +0).
template <typename Program>
inline void TriangleRasterizer<Program>::shadeAlphaRowHalf4(const SetupTriangle& t, int bx, int py, std::uint32_t live,
                                                            float centerX0, float fy) {
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
template <typename Program>
inline __m128 TriangleRasterizer<Program>::alpha4(int h, std::uint32_t lanes) const {
    const int o = 4 * h;
    const float* duv[4] = {row_.duv[0] + o, row_.duv[1] + o, row_.duv[2] + o, row_.duv[3] + o};
    return program_.alpha4(row_.color[3] + o, row_.uv[0] + o, row_.uv[1] + o, duv, lanes);
}

// The alpha-first row under a Keep alpha test (alphaFirst_, hasAlphaFirstHooks): the texel alpha four lanes
// at a time (the general sampler's bits), then the alpha test on the alpha shade()
// would output, (baseColorFactor.a * vertex alpha) * texel alpha (toStraight keeps
// alpha), and the texel's colour, the normals and colours and shade() for the fragments
// that pass only, in the halves that hold one: a discarded fragment writes nothing, so
// none of them is ever needed.
template <typename Program>
inline void TriangleRasterizer<Program>::shadeAlphaTestedRow(const SetupTriangle& t, int bx, int py, std::uint32_t live,
                                                             float centerX0, float fy, const float* z,
                                                             std::byte* depthAt) {
    const AlphaSampler* sampler = rowSampler_;
    if (!sampler) {  // alpha4 without a texture: factor * vertex alpha
        interpolateRow(t, centerX0, fy, live);
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
    const float factorAlpha = program_.alphaTestFactor();
    for (int h = 0; h < 2; ++h) {
        const std::uint32_t lanes = (live >> (4 * h)) & 0xFu;
        if (!lanes) continue;
        const int o = 4 * h;
        interpolateHalf(t, centerX0, fy, h, RowInputs::AlphaInputs);
        const AlphaSampler::Lookup4 lookup = sampler->lookup4(row_.uv[0] + o, row_.uv[1] + o, row_.duv[0] + o,
                                                              row_.duv[1] + o, row_.duv[2] + o, row_.duv[3] + o, lanes);
        alignas(16) float texelAlpha[4];
        _mm_store_ps(texelAlpha, sampler->alpha4(lookup));
        std::uint32_t passing = 0;
        for (std::uint32_t bits = lanes; bits; bits &= bits - 1) {
            const int k = __builtin_ctz(bits);
            if (draw_.alphaTest.passes(factorAlpha * row_.color[3][o + k] * texelAlpha[k])) passing |= 1u << k;
        }
        counters_.pixelsShaded += kBitCount[lanes & ~passing];  // shaded as far as their alpha
        if (!passing) continue;
        interpolateHalf(t, centerX0, fy, h, RowInputs::Rest);  // normals and colours for the passing
        shadeTexels(t, lookup, bx, py, o, passing, z, depthAt);
    }
}

// A row with the texture sampled four lanes at a time (sampledRow_, hasSampledRowHooks): the
// general path's shade() of each live lane, its sampleTexture() taken from rgba4 (the same
// bits), which finds each lane's level and texels in SIMD and reads no format per texel.
template <typename Program>
inline void TriangleRasterizer<Program>::shadeSampledRow(const SetupTriangle& t, int bx, int py, std::uint32_t live,
                                                         float centerX0, float fy, const float* z, std::byte* depthAt) {
    interpolateRow(t, centerX0, fy, live);
    const AlphaSampler& sampler = *rowSampler_;
    for (int h = 0; h < 2; ++h) {
        const std::uint32_t lanes = (live >> (4 * h)) & 0xFu;
        if (!lanes) continue;
        const int o = 4 * h;
        shadeTexels(t,
                    sampler.lookup4(row_.uv[0] + o, row_.uv[1] + o, row_.duv[0] + o, row_.duv[1] + o, row_.duv[2] + o,
                                    row_.duv[3] + o, lanes),
                    bx, py, o, lanes, z, depthAt);
    }
}

// shadeSampled() and the writes of lanes o + k (k set in `lanes`) of a block row, their
// texels those `lookup` finds.
template <typename Program>
inline void TriangleRasterizer<Program>::shadeTexels(const SetupTriangle& t, const AlphaSampler::Lookup4& lookup,
                                                     int bx, int py, int o, std::uint32_t lanes, const float* z,
                                                     std::byte* depthAt) {
    alignas(16) float texels[4][4] = {};
    rowSampler_->rgba4(lookup, lanes, texels);
    if (packedWrite_ && kBitCount[lanes] >= 2) {  // a lone lane is shaded faster by itself
        shadePacked4(texels, t.frontFacing, bx, py, o, lanes, z, depthAt);
        return;
    }
    for (std::uint32_t bits = lanes; bits; bits &= bits - 1) {
        const int k = __builtin_ctz(bits), i = o + k;
        const glm::vec4 texel(texels[k][0], texels[k][1], texels[k][2], texels[k][3]);
        writeShaded(program_.shadeSampled(rowFragment(t, bx + i, py, i), texel), bx + i, py, z[i],
                    depthAt + i * sizeof(float));
    }
}

// shadeTexels where the draw writes one plain RGBA8 target (packedWrite_): the four lanes
// shaded at once (shadeSampled4) and encoded at once (encodeSrgb8x4, encodeUnorm8x4: the
// bytes storeRgba8Srgb and storeRgba8Unorm store), then what writeShaded does per lane with
// them: the alpha test's writes, the depth, and the four bytes as one store.
template <typename Program>
inline void TriangleRasterizer<Program>::shadePacked4(const float (&texels)[4][4], bool frontFacing, int bx, int py,
                                                      int o, std::uint32_t lanes, const float* z, std::byte* depthAt) {
    __m128 texel[4] = {_mm_load_ps(texels[0]), _mm_load_ps(texels[1]), _mm_load_ps(texels[2]), _mm_load_ps(texels[3])};
    _MM_TRANSPOSE4_PS(texel[0], texel[1], texel[2], texel[3]);  // lanes to channels
    const float* const color[4] = {row_.color[0] + o, row_.color[1] + o, row_.color[2] + o, row_.color[3] + o};
    const float* const normal[3] = {row_.normal[0] + o, row_.normal[1] + o, row_.normal[2] + o};
    __m128 shaded[4];
    program_.shadeSampled4(texel, color, normal, frontFacing, shaded);
    const bool srgb = color_[0].srgb8Plain;
    __m128i packed = srgb ? encodeSrgb8x4(shaded[0]) : encodeUnorm8x4(shaded[0]);
    for (int c = 1; c < 3; ++c)
        packed =
            _mm_or_si128(packed, _mm_slli_epi32(srgb ? encodeSrgb8x4(shaded[c]) : encodeUnorm8x4(shaded[c]), 8 * c));
    packed = _mm_or_si128(packed, _mm_slli_epi32(encodeUnorm8x4(shaded[3]), 24));
    alignas(16) std::uint32_t bytes[4];
    alignas(16) float alpha[4];
    _mm_store_si128(reinterpret_cast<__m128i*>(bytes), packed);
    _mm_store_ps(alpha, shaded[3]);
    for (std::uint32_t bits = lanes; bits; bits &= bits - 1) {
        const int k = __builtin_ctz(bits), i = o + k;
        ++counters_.pixelsShaded;
        const AlphaTestWrites writes = alphaTestWrites(draw_.alphaTest, alpha[k], draw_.depthWrite);
        if (writes.discard) continue;
        if (writes.depth) std::memcpy(depthAt + i * sizeof(float), &z[i], sizeof(float));
        std::byte* p = color_[0].at(bx + i, py);
        if (writes.channels == WriteAll) {
            std::memcpy(p, &bytes[k], sizeof bytes[k]);
        } else if (writes.channels) {
            alignas(16) float lane[4][4];
            for (int c = 0; c < 4; ++c) _mm_store_ps(lane[c], shaded[c]);
            writeColor(0, p, glm::vec4(lane[0][k], lane[1][k], lane[2][k], lane[3][k]), writes.channels);
        }
    }
}

// interpolate() for the lanes of a block row (pixel bx + i in lane i) in the halves of the
// row that hold a lane of `lanes`, lane by lane the same IEEE operations in the same
// order (the division included), into row_.
template <typename Program>
inline void TriangleRasterizer<Program>::interpolateRow(const SetupTriangle& t, float centerX0, float fy,
                                                        std::uint32_t lanes) {
    for (int h = 0; h < 2; ++h)
        if ((lanes >> (4 * h)) & 0xFu) interpolateHalf(t, centerX0, fy, h);
}

template <typename Program>
inline void TriangleRasterizer<Program>::interpolateHalf(const SetupTriangle& t, float centerX0, float fy, int h,
                                                         RowInputs inputs) {
    constexpr ProgramNeeds needs = Program::kNeeds;
    if constexpr (needs.anyAttribute()) {
        const __m128 fx = _mm_sub_ps(_mm_add_ps(_mm_set1_ps(centerX0), _mm_setr_ps(float(4 * h), float(4 * h + 1),
                                                                                   float(4 * h + 2), float(4 * h + 3))),
                                     _mm_set1_ps(t.originX));
        auto evaluateLanes = [&](const Plane& p) {
            return _mm_add_ps(_mm_add_ps(_mm_set1_ps(p.value), _mm_mul_ps(_mm_set1_ps(p.dx), fx)),
                              _mm_set1_ps(p.dy * fy));
        };
        const bool alphaInputs = inputs != RowInputs::Rest, rest = inputs != RowInputs::AlphaInputs;
        __m128 w;
        if (alphaInputs) {
            w = _mm_div_ps(_mm_set1_ps(1.0f), evaluateLanes(t.inverseW));
            _mm_store_ps(row_.w + 4 * h, w);
        } else {
            w = _mm_load_ps(row_.w + 4 * h);  // the AlphaInputs call's
        }
        auto attribute = [&](int k) { return _mm_mul_ps(evaluateLanes(t.attributeOverW[k]), w); };
        if constexpr (needs.uv) {
            if (alphaInputs) {
                const __m128 u = attribute(kAttrU), v = attribute(kAttrV);
                _mm_store_ps(row_.uv[0] + 4 * h, u);
                _mm_store_ps(row_.uv[1] + 4 * h, v);
                if constexpr (needs.derivatives) {
                    const Plane& pu = t.attributeOverW[kAttrU];
                    const Plane& pv = t.attributeOverW[kAttrV];
                    auto derivative = [&](float slope, __m128 value, float inverseWSlope) {
                        return _mm_mul_ps(_mm_sub_ps(_mm_set1_ps(slope), _mm_mul_ps(value, _mm_set1_ps(inverseWSlope))),
                                          w);
                    };
                    _mm_store_ps(row_.duv[0] + 4 * h, derivative(pu.dx, u, t.inverseW.dx));
                    _mm_store_ps(row_.duv[1] + 4 * h, derivative(pv.dx, v, t.inverseW.dx));
                    _mm_store_ps(row_.duv[2] + 4 * h, derivative(pu.dy, u, t.inverseW.dy));
                    _mm_store_ps(row_.duv[3] + 4 * h, derivative(pv.dy, v, t.inverseW.dy));
                }
            }
        }
        if constexpr (needs.normal)
            if (rest)
                for (int k = 0; k < 3; ++k) _mm_store_ps(row_.normal[k] + 4 * h, attribute(kAttrNormal + k));
        if constexpr (needs.color) {
            if (rest)
                for (int k = 0; k < 3; ++k) _mm_store_ps(row_.color[k] + 4 * h, attribute(kAttrColor + k));
            if (alphaInputs) _mm_store_ps(row_.color[3] + 4 * h, attribute(kAttrColor + 3));
        }
        if constexpr (needs.colorAlpha)
            if (alphaInputs) _mm_store_ps(row_.color[3] + 4 * h, attribute(kAttrColor + 3));
    }
}

// The fragment of lane i from row_ (what interpolate() gives for that pixel).
template <typename Program>
inline Fragment TriangleRasterizer<Program>::rowFragment(const SetupTriangle& t, int px, int py, int i) const {
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
#endif  // SOFT_RASTER_SSE2

}  // namespace
}  // namespace raster
}  // namespace engine::render::soft
