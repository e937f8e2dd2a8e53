// SPDX-License-Identifier: MIT
#pragma once
// The tile rasterizer's building blocks (program-authoring header): depth rows, target
// views, per-channel blend tables and the 8-bit stores, shared by every instantiation of
// TriangleRasterizer (triangle_rasterizer.hpp). Inline so that a module's translation unit
// instantiates the rasterizer for its own program with the same arithmetic as the driver's.
#include <array>
#include <cstdint>
#include <cstring>

#if defined(__SSE2__) && !defined(SOFT_RASTER_SCALAR)
#include <emmintrin.h>
#define SOFT_RASTER_SSE2 1
#endif

#include <glm/glm.hpp>

#include "engine/render/pixel_codec.hpp"
#include "engine/render/kernel/detail/blend.hpp"
#include "engine/render/kernel/detail/draw_state.hpp"
#include "engine/render/kernel/detail/one_one_half_blend.hpp"
#include "engine/render/kernel/detail/same_bits.hpp"
#include "engine/render/kernel/soft_texture.hpp"
#include "engine/render/kernel/detail/triangle_setup.hpp"

namespace engine::render::soft::raster {
// Internal linkage in every translation unit that instantiates the rasterizer, as when these
// lived in the driver's own .cpp: GCC inlines a static function called once, not an inline one.
namespace {

inline constexpr int kBlockSize = 8;
inline constexpr std::int64_t kPixelStep = kSubpixelScale;
inline constexpr std::int64_t kHalfPixel = kSubpixelScale / 2;
inline constexpr int kSampleOffsetScale = kSubpixelScale / 16;  // sample offsets are in 1/16 pixel

inline float loadDepth(const std::byte* p) {
    float z;
    std::memcpy(&z, p, sizeof z);
    return z;
}

inline float evaluate(const Plane& plane, float x, float y) { return plane.value + plane.dx * x + plane.dy * y; }

// Set bits of a block row's 8-bit lane mask.
inline constexpr std::array<std::uint8_t, 256> kBitCount = [] {
    std::array<std::uint8_t, 256> n{};
    for (int i = 1; i < 256; ++i) n[i] = std::uint8_t(n[i >> 1] + (i & 1));
    return n;
}();

// Depth test of one block row of a single-sampled target: 8 lanes, pixel bx + i in lane
// i (centerX0 = float(bx) + 0.5f), `coverage` the covered lanes (never one outside the
// target). Per lane exactly the per-pixel path's arithmetic (IEEE mul/add in the same
// order, so SIMD lanes give the same bits):
//   fx = (float(bx + i) + 0.5f) - originX,  z = clamp01(value + dx * fx + dy * fy)
// Returns the covered lanes where `z <Func> stored` holds; without Write writes z[8] (for
// the shading that follows), with Write (depth-only draws) stores z into those lanes of
// `stored` (8 floats, any alignment), rewriting the other lanes with the values they had.
template <CompareFunc Func, bool Write>
inline std::uint32_t depthRow(const Plane& plane, float centerX0, float originX, float fy, std::uint32_t coverage,
                              std::byte* stored, float* z) {
#if SOFT_RASTER_SSE2
    const __m128 value = _mm_set1_ps(plane.value), dx = _mm_set1_ps(plane.dx);
    const __m128 dyFy = _mm_set1_ps(plane.dy * fy);
    const __m128 zero = _mm_setzero_ps(), one = _mm_set1_ps(1.0f), origin = _mm_set1_ps(originX);
    // Lane i of the half h covered when bit 4h + i of `coverage` is set.
    const __m128i laneBits = _mm_setr_epi32(1, 2, 4, 8);
    float* const depth = reinterpret_cast<float*>(stored);  // intrinsic loads/stores may alias
    std::uint32_t mask = 0;
    for (int h = 0; h < 2; ++h) {
        // float(bx) + 0.5f + i is exact, as float(bx + i) + 0.5f is.
        const __m128 center = _mm_add_ps(
            _mm_set1_ps(centerX0), _mm_setr_ps(float(4 * h), float(4 * h + 1), float(4 * h + 2), float(4 * h + 3)));
        const __m128 fx = _mm_sub_ps(center, origin);
        const __m128 v = _mm_add_ps(_mm_add_ps(value, _mm_mul_ps(dx, fx)), dyFy);
        // clamp01: maxps(v, 0) gives 0 for v <= 0 and NaN, then minps(., 1).
        const __m128 zv = _mm_min_ps(_mm_max_ps(v, zero), one);
        if constexpr (!Write) _mm_storeu_ps(z + 4 * h, zv);
        const __m128 d = _mm_loadu_ps(depth + 4 * h);
        __m128 pass = zero;
        switch (Func) {
            case CompareFunc::Never: pass = zero; break;
            case CompareFunc::Less: pass = _mm_cmplt_ps(zv, d); break;
            case CompareFunc::Equal: pass = _mm_cmpeq_ps(zv, d); break;
            case CompareFunc::LessEqual: pass = _mm_cmple_ps(zv, d); break;
            case CompareFunc::Greater: pass = _mm_cmpgt_ps(zv, d); break;
            case CompareFunc::NotEqual: pass = _mm_cmpneq_ps(zv, d); break;  // true for NaN, as !=
            case CompareFunc::GreaterEqual: pass = _mm_cmpge_ps(zv, d); break;
            case CompareFunc::Always: pass = _mm_cmpeq_ps(zero, zero); break;
        }
        const __m128i covered =
            _mm_cmpeq_epi32(_mm_and_si128(_mm_set1_epi32(int(coverage >> (4 * h))), laneBits), laneBits);
        const __m128 live = _mm_and_ps(pass, _mm_castsi128_ps(covered));
        mask |= std::uint32_t(_mm_movemask_ps(live)) << (4 * h);
        if constexpr (Write) _mm_storeu_ps(depth + 4 * h, _mm_or_ps(_mm_and_ps(live, zv), _mm_andnot_ps(live, d)));
    }
    return mask;
#else
    std::uint32_t mask = 0;
    for (int i = 0; i < 8; ++i) {
        const float fx = (centerX0 + float(i)) - originX;
        z[i] = clamp01(evaluate(plane, fx, fy));
        float d;
        std::memcpy(&d, stored + i * sizeof(float), sizeof d);
        if (!((coverage >> i) & 1u) || !compare(Func, z[i], d)) continue;
        mask |= 1u << i;
        if constexpr (Write) std::memcpy(stored + i * sizeof(float), &z[i], sizeof(float));
    }
    return mask;
#endif
}

// A fully covered block of a depth-only draw (test and write): rows py0..py1 of the 8
// pixels at row0 (rowBytes apart), all inside the target. Returns the pixels that passed.
template <CompareFunc Func>
inline std::uint64_t depthOnlyBlock(const SetupTriangle& t, float centerX0, int py0, int py1, std::uint32_t coverage,
                                    std::byte* row0, std::size_t rowBytes) {
    std::uint64_t passed = 0;
    float unused[8];
    for (int py = py0; py <= py1; ++py) {
        const float fy = float(py) + 0.5f - t.originY;
        const std::uint32_t live = depthRow<Func, true>(t.depth, centerX0, t.originX, fy, coverage,
                                                        row0 + std::size_t(py - py0) * rowBytes, unused);
        passed += kBitCount[live];
    }
    return passed;
}

using DepthOnlyBlockFn = std::uint64_t (*)(const SetupTriangle&, float, int, int, std::uint32_t, std::byte*,
                                           std::size_t);
inline DepthOnlyBlockFn depthOnlyBlockFunction(CompareFunc func) {
    switch (func) {
        case CompareFunc::Never: return depthOnlyBlock<CompareFunc::Never>;
        case CompareFunc::Less: return depthOnlyBlock<CompareFunc::Less>;
        case CompareFunc::Equal: return depthOnlyBlock<CompareFunc::Equal>;
        case CompareFunc::LessEqual: return depthOnlyBlock<CompareFunc::LessEqual>;
        case CompareFunc::Greater: return depthOnlyBlock<CompareFunc::Greater>;
        case CompareFunc::NotEqual: return depthOnlyBlock<CompareFunc::NotEqual>;
        case CompareFunc::GreaterEqual: return depthOnlyBlock<CompareFunc::GreaterEqual>;
        case CompareFunc::Always: return depthOnlyBlock<CompareFunc::Always>;
    }
    return depthOnlyBlock<CompareFunc::Always>;
}

using DepthRowFn = std::uint32_t (*)(const Plane&, float, float, float, std::uint32_t, std::byte*, float*);
template <bool Write>
DepthRowFn depthRowFunction(CompareFunc func) {
    switch (func) {
        case CompareFunc::Never: return depthRow<CompareFunc::Never, Write>;
        case CompareFunc::Less: return depthRow<CompareFunc::Less, Write>;
        case CompareFunc::Equal: return depthRow<CompareFunc::Equal, Write>;
        case CompareFunc::LessEqual: return depthRow<CompareFunc::LessEqual, Write>;
        case CompareFunc::Greater: return depthRow<CompareFunc::Greater, Write>;
        case CompareFunc::NotEqual: return depthRow<CompareFunc::NotEqual, Write>;
        case CompareFunc::GreaterEqual: return depthRow<CompareFunc::GreaterEqual, Write>;
        case CompareFunc::Always: return depthRow<CompareFunc::Always, Write>;
    }
    return depthRow<CompareFunc::Always, Write>;
}

// What a shaded fragment still writes after the alpha test in the GS sense ([PCSX2]): a
// passing fragment writes colour, alpha and (when the draw writes depth) depth; a failing one
// what its fail mode keeps, nothing at all for Keep (`discard`).
struct AlphaTestWrites {
    bool discard;
    std::uint8_t channels;  // ColorWrite bits
    bool depth;
};

inline AlphaTestWrites alphaTestWrites(const AlphaTest& test, float alpha, bool depthWrite) {
    if (test.passes(alpha)) return {false, WriteAll, depthWrite};
    switch (test.failMode) {
        case AlphaFailMode::Keep: return {true, 0, false};
        case AlphaFailMode::FbOnly: return {false, WriteAll, false};
        case AlphaFailMode::ZbOnly: return {false, 0, depthWrite};
        case AlphaFailMode::RgbOnly: return {false, WriteRGB, false};
    }
    return {false, WriteAll, depthWrite};
}

// Where a single-sampled target's pixels are, and how a draw writes them.
struct TargetView {
    std::byte* base = nullptr;
    std::size_t rowBytes = 0;
    int pixelBytes = 0;
    Format format = Format::RGBA8_UNORM;
    bool blend = false;
    bool normalized = false;
    bool rgba8Plain = false;  // RGBA8_UNORM, all four channels, no blending: a 4-byte store
    bool srgb8Plain = false;  // RGBA8_SRGB, all four channels, no blending: storeRgba8Srgb
    bool byteLut = false;     // RGBA8 blend whose every stored byte is a function of that byte alone
    bool zeroKeeps = false;   // blended so that a (0, 0, 0, 0) source stores back what is there (zeroSourceKeeps)
    std::byte* at(int x, int y) const { return base + std::size_t(y) * rowBytes + std::size_t(x) * pixelBytes; }
};

// Whether a blend onto an RGBA8 (UNORM or sRGB) target makes each result channel a function of
// the same destination channel alone, given the source and constant: true unless an RGB
// factor reads destination alpha (DST_ALPHA, INV_DST_ALPHA, SRC_ALPHA_SAT). The alpha
// result only ever reads destination alpha.
inline bool blendIsPerChannel(const BlendState& b) {
    if (b.opRgb == BlendOp::Min || b.opRgb == BlendOp::Max) return true;  // factors ignored
    auto readsDstAlpha = [](BlendFactor f) {
        return f == BlendFactor::DstAlpha || f == BlendFactor::InvDstAlpha || f == BlendFactor::SrcAlphaSat;
    };
    return !readsDstAlpha(b.srcRgb) && !readsDstAlpha(b.dstRgb);
}

// The minimum covered-box area (pixels in one tile) for which a constant-colour blend is
// done through a 256-entry table per channel rather than per pixel.
inline constexpr int kBlendLutMinPixels = 512;

// Per-channel blend tables, one per colour target slot, kept per thread from tile to tile.
// A table is identified by everything it is computed from, so a stale one is never used.
struct BlendLut {
    bool valid = false;
    BlendState blend;
    glm::vec4 constant{0.0f};
    Format format = Format::RGBA8_UNORM;
    glm::vec4 color{0.0f};
    std::array<std::array<std::byte, 256>, 4> bytes;  // [channel][stored byte]

    bool matches(const BlendState& b, const glm::vec4& k, Format f, const glm::vec4& c) const {
        return valid && f == format && sameBits(c, color) && sameBits(k, constant) && b.srcRgb == blend.srcRgb &&
               b.dstRgb == blend.dstRgb && b.opRgb == blend.opRgb && b.srcAlpha == blend.srcAlpha &&
               b.dstAlpha == blend.dstAlpha && b.opAlpha == blend.opAlpha && b.enabled == blend.enabled;
    }
};
inline thread_local std::array<BlendLut, kMaxColorTargets> tBlendLuts;

inline void storeRgba8Unorm(std::byte* p, const glm::vec4& v) {
    p[0] = std::byte{encodeUnorm8(v.x)};
    p[1] = std::byte{encodeUnorm8(v.y)};
    p[2] = std::byte{encodeUnorm8(v.z)};
    p[3] = std::byte{encodeUnorm8(v.w)};
}
// storeTexel(p, RGBA8_SRGB, v, WriteAll) without its per-channel format switch.
inline void storeRgba8Srgb(std::byte* p, const glm::vec4& v) {
    p[0] = std::byte{encodeSrgb8(v.x)};
    p[1] = std::byte{encodeSrgb8(v.y)};
    p[2] = std::byte{encodeSrgb8(v.z)};
    p[3] = std::byte{encodeUnorm8(v.w)};
}

// Whether every 8-bit code decodes (byteTables()) and encodes back to itself, UNORM and sRGB
// (checked once here rather than assumed): then a blend whose result is the decoded stored
// value stores the byte that was there.
inline bool bytesRoundTrip() {
    static const bool roundTrip = [] {
        const ByteTables& t = byteTables();
        for (int b = 0; b < 256; ++b)
            if (encodeUnorm8(t.unorm[b]) != b || encodeSrgb8(t.srgb[b]) != b) return false;
        return true;
    }();
    return roundTrip;
}

// Whether blending a source of (0, 0, 0, 0) (either zero's sign) onto an 8-bit target leaves
// every stored byte as it is, so the blend can be skipped. Normalized targets clamp source,
// destination and constant to [0, 1] (blend.hpp), so every factor is finite and the source
// terms are +-0. ADD: +-0 + d * df = d when the destination factors are exactly 1 for a zero
// source (ONE, INV_SRC_ALPHA, INV_SRC_COLOR); MAX ignores the factors: max(+-0, d) = d, or
// -0 where d is +0, which encodes as the same byte. The decoded byte then encodes back to
// itself (bytesRoundTrip: checked for every byte, UNORM and sRGB).
inline bool zeroSourceKeeps(Format format, const BlendState& b) {
    const bool eightBit = format == Format::RGBA8_UNORM || format == Format::RGBA8_SRGB || format == Format::R8_UNORM ||
                          format == Format::RG8_UNORM;
    auto keeps = [](BlendOp op, BlendFactor dst) {
        if (op == BlendOp::Max) return true;
        return op == BlendOp::Add &&
               (dst == BlendFactor::One || dst == BlendFactor::InvSrcAlpha || dst == BlendFactor::InvSrcColor);
    };
    return eightBit && bytesRoundTrip() && keeps(b.opRgb, b.dstRgb) && keeps(b.opAlpha, b.dstAlpha);
}

// BlendState::alphaOverKeepAlpha, found by its factors: colour SRC_ALPHA / INV_SRC_ALPHA ADD,
// alpha ZERO / ONE ADD (the target keeps its alpha), all channels written (e.g. a mask
// composite, [Hathaway 2010] §3.5.4).
inline bool isAlphaOverKeepingAlpha(const BlendState& b) {
    return b.enabled && b.srcRgb == BlendFactor::SrcAlpha && b.dstRgb == BlendFactor::InvSrcAlpha &&
           b.opRgb == BlendOp::Add && b.srcAlpha == BlendFactor::Zero && b.dstAlpha == BlendFactor::One &&
           b.opAlpha == BlendOp::Add && b.writeMask == WriteAll;
}
inline bool isRgba8(const SoftTexture* t) {
    return t && t->desc.samples == 1 && (t->desc.format == Format::RGBA8_UNORM || t->desc.format == Format::RGBA8_SRGB);
}

#if SOFT_RASTER_SSE2
// encodeUnorm8 of each lane, as a 32-bit integer: 0 unless v > 0 (NaN too), 255 from 1 on,
// else v * 255 + 0.5 truncated (the same IEEE mul and add).
inline __m128i encodeUnorm8x4(__m128 v) {
    const __m128i rounded = _mm_cvttps_epi32(_mm_add_ps(_mm_mul_ps(v, _mm_set1_ps(255.0f)), _mm_set1_ps(0.5f)));
    const __m128i positive = _mm_castps_si128(_mm_cmpgt_ps(v, _mm_setzero_ps()));
    const __m128i full = _mm_castps_si128(_mm_cmpge_ps(v, _mm_set1_ps(1.0f)));
    return _mm_or_si128(_mm_and_si128(full, _mm_set1_epi32(255)),
                        _mm_andnot_si128(full, _mm_and_si128(positive, rounded)));
}

// encodeSrgb8 of each lane, as a 32-bit integer: the same clamp (maxps and minps are its
// compare-selects, NaN to 0), bucket and one threshold comparison.
inline __m128i encodeSrgb8x4(__m128 v) {
    const __m128 clamped = _mm_min_ps(_mm_max_ps(v, _mm_setzero_ps()), _mm_set1_ps(1.0f));
    const SrgbEncodeTables& t = srgbEncodeTables();
    alignas(16) std::uint32_t bucket[4];
    _mm_store_si128(reinterpret_cast<__m128i*>(bucket), _mm_srli_epi32(_mm_castps_si128(clamped), 16));
    const __m128i start =
        _mm_setr_epi32(t.start[bucket[0]], t.start[bucket[1]], t.start[bucket[2]], t.start[bucket[3]]);
    alignas(16) std::int32_t code[4];
    _mm_store_si128(reinterpret_cast<__m128i*>(code), start);
    const __m128 next = _mm_setr_ps(t.threshold[code[0] + 1], t.threshold[code[1] + 1], t.threshold[code[2] + 1],
                                    t.threshold[code[3] + 1]);
    // The comparison's all-ones lanes are -1: subtracting adds the step.
    return _mm_sub_epi32(start, _mm_castps_si128(_mm_cmpge_ps(clamped, next)));
}

// Lanes (bit i: pixel i of the 4 RGBA8 pixels at p) whose stored bytes, with the bytes a
// write mask leaves set to 0xFF in `unwritten`, are all 0xFF.
inline std::uint32_t saturatedLanes(const std::byte* p, std::uint32_t unwritten) {
    const __m128i stored =
        _mm_or_si128(_mm_loadu_si128(reinterpret_cast<const __m128i*>(p)), _mm_set1_epi32(int(unwritten)));
    return std::uint32_t(_mm_movemask_ps(_mm_castsi128_ps(_mm_cmpeq_epi32(stored, _mm_set1_epi32(-1)))));
}

// blendOneOneRgba8 of the 4 RGBA8_UNORM pixels at p, pixel i with alpha a[i] in [0, 1], for
// the lanes set in `lanes`; the other pixels are stored back as they were. Per channel the
// same operations: MAX max(encode(a), d), ADD encode(a + d / 255) with d / 255 the unorm
// table's value (byteTables(): float(d) / 255.0f, one correctly rounded division).
inline void blendOneOneRgba8x4(const BlendState& b, std::byte* p, __m128 a, std::uint32_t lanes) {
    __m128i* at = reinterpret_cast<__m128i*>(p);
    const __m128i stored = _mm_loadu_si128(at);
    const __m128i encoded = encodeUnorm8x4(a);
    __m128i blended = _mm_setzero_si128();
    for (int c = 0; c < 4; ++c) {
        const __m128i d = _mm_and_si128(_mm_srli_epi32(stored, 8 * c), _mm_set1_epi32(0xFF));
        __m128i out = d;
        if (b.writeMask & (1u << c)) {
            if ((c < 3 ? b.opRgb : b.opAlpha) == BlendOp::Max) {
                out = _mm_max_epi16(encoded, d);  // both in [0, 255]: the 16-bit max is the max
            } else {
                out = encodeUnorm8x4(_mm_add_ps(a, _mm_div_ps(_mm_cvtepi32_ps(d), _mm_set1_ps(255.0f))));
            }
        }
        blended = _mm_or_si128(blended, _mm_slli_epi32(out, 8 * c));
    }
    const __m128i bits = _mm_setr_epi32(1, 2, 4, 8);
    const __m128i write = _mm_cmpeq_epi32(_mm_and_si128(_mm_set1_epi32(int(lanes)), bits), bits);
    _mm_storeu_si128(at, _mm_or_si128(_mm_and_si128(write, blended), _mm_andnot_si128(write, stored)));
}
#endif

}  // namespace
}  // namespace engine::render::soft::raster
