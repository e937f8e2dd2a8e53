#include "tile_rasterizer.hpp"

#include <algorithm>
#include <array>
#include <cstring>
#include <type_traits>

#if defined(__SSE2__) && !defined(SSAM_SOFT_SCALAR)
#include <emmintrin.h>
#define SSAM_SOFT_SSE2 1
#endif

#include "blend.hpp"
#include "engine/render/pixel_codec.hpp"
#include "one_one_half_blend.hpp"

namespace engine::render::soft {
namespace {

constexpr int kBlockSize = 8;
constexpr std::int64_t kPixelStep = kSubpixelScale;
constexpr std::int64_t kHalfPixel = kSubpixelScale / 2;
constexpr int kSampleOffsetScale = kSubpixelScale / 16;  // sample offsets are in 1/16 pixel

float loadDepth(const std::byte* p) {
    float z;
    std::memcpy(&z, p, sizeof z);
    return z;
}

float evaluate(const Plane& plane, float x, float y) { return plane.value + plane.dx * x + plane.dy * y; }

// Set bits of a block row's 8-bit lane mask.
constexpr std::array<std::uint8_t, 256> kBitCount = [] {
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
std::uint32_t depthRow(const Plane& plane, float centerX0, float originX, float fy, std::uint32_t coverage,
                       std::byte* stored, float* z) {
#if SSAM_SOFT_SSE2
    const __m128 value = _mm_set1_ps(plane.value), dx = _mm_set1_ps(plane.dx);
    const __m128 dyFy = _mm_set1_ps(plane.dy * fy);
    const __m128 zero = _mm_setzero_ps(), one = _mm_set1_ps(1.0f), origin = _mm_set1_ps(originX);
    // Lane i of the half h covered when bit 4h + i of `coverage` is set.
    const __m128i laneBits = _mm_setr_epi32(1, 2, 4, 8);
    float* const depth = reinterpret_cast<float*>(stored);  // intrinsic loads/stores may alias
    std::uint32_t mask = 0;
    for (int h = 0; h < 2; ++h) {
        // float(bx) + 0.5f + i is exact, as float(bx + i) + 0.5f is.
        const __m128 center = _mm_add_ps(_mm_set1_ps(centerX0), _mm_setr_ps(float(4 * h), float(4 * h + 1),
                                                                             float(4 * h + 2), float(4 * h + 3)));
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
std::uint64_t depthOnlyBlock(const SetupTriangle& t, float centerX0, int py0, int py1, std::uint32_t coverage,
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

using DepthOnlyBlockFn = std::uint64_t (*)(const SetupTriangle&, float, int, int, std::uint32_t, std::byte*, std::size_t);
DepthOnlyBlockFn depthOnlyBlockFunction(CompareFunc func) {
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
    std::byte* at(int x, int y) const { return base + std::size_t(y) * rowBytes + std::size_t(x) * pixelBytes; }
};

// Whether a blend onto an RGBA8 (UNORM or sRGB) target makes each result channel a function of
// the same destination channel alone, given the source and constant: true unless an RGB
// factor reads destination alpha (DST_ALPHA, INV_DST_ALPHA, SRC_ALPHA_SAT). The alpha
// result only ever reads destination alpha.
bool blendIsPerChannel(const BlendState& b) {
    if (b.opRgb == BlendOp::Min || b.opRgb == BlendOp::Max) return true;  // factors ignored
    auto readsDstAlpha = [](BlendFactor f) {
        return f == BlendFactor::DstAlpha || f == BlendFactor::InvDstAlpha || f == BlendFactor::SrcAlphaSat;
    };
    return !readsDstAlpha(b.srcRgb) && !readsDstAlpha(b.dstRgb);
}

// The minimum covered-box area (pixels in one tile) for which a constant-colour blend is
// done through a 256-entry table per channel rather than per pixel.
constexpr int kBlendLutMinPixels = 512;

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
        return valid && f == format && std::memcmp(&c, &color, sizeof c) == 0 &&
               std::memcmp(&k, &constant, sizeof k) == 0 && b.srcRgb == blend.srcRgb && b.dstRgb == blend.dstRgb &&
               b.opRgb == blend.opRgb && b.srcAlpha == blend.srcAlpha && b.dstAlpha == blend.dstAlpha &&
               b.opAlpha == blend.opAlpha && b.enabled == blend.enabled;
    }
};
thread_local std::array<BlendLut, kMaxColorTargets> tBlendLuts;

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
bool bytesRoundTrip() {
    static const bool roundTrip = [] {
        const ByteTables& t = byteTables();
        for (int b = 0; b < 256; ++b)
            if (encodeUnorm8(t.unorm[b]) != b || encodeSrgb8(t.srgb[b]) != b) return false;
        return true;
    }();
    return roundTrip;
}

// The SSAM composite's blend (seeds/000 §3.5.4): colour SRC_ALPHA / INV_SRC_ALPHA ADD, alpha
// ZERO / ONE ADD (the target keeps its alpha), all channels written.
bool isCompositeBlend(const BlendState& b) {
    return b.enabled && b.srcRgb == BlendFactor::SrcAlpha && b.dstRgb == BlendFactor::InvSrcAlpha &&
           b.opRgb == BlendOp::Add && b.srcAlpha == BlendFactor::Zero && b.dstAlpha == BlendFactor::One &&
           b.opAlpha == BlendOp::Add && b.writeMask == WriteAll;
}
// fetchTexel(t, x, y)[c] (loadTexel's channel c), with the formats SSAM's masks come in
// read without decoding the other channels: RGBA8_UNORM through the table, half floats
// through decodeHalf (a channel the format lacks takes loadTexel's default).
inline float texelChannel(const SoftTexture& t, int x, int y, int c) {
    const std::byte* p = t.texel(0, x, y);
    std::uint16_t half;
    switch (t.desc.format) {
        case Format::RGBA8_UNORM: return byteTables().unorm[std::to_integer<std::uint8_t>(p[c])];
        case Format::R16F:
        case Format::RG16F:
        case Format::RGBA16F: {
            const int channels = t.desc.format == Format::R16F ? 1 : t.desc.format == Format::RG16F ? 2 : 4;
            if (c >= channels) break;
            std::memcpy(&half, p + 2 * c, sizeof half);
            return decodeHalf(half);
        }
        default: break;
    }
    return loadTexel(p, t.desc.format)[c];
}
bool isRgba8(const SoftTexture* t) {
    return t && t->desc.samples == 1 && (t->desc.format == Format::RGBA8_UNORM || t->desc.format == Format::RGBA8_SRGB);
}

#if SSAM_SOFT_SSE2
// encodeUnorm8 of each lane, as a 32-bit integer: 0 unless v > 0 (NaN too), 255 from 1 on,
// else v * 255 + 0.5 truncated (the same IEEE mul and add).
inline __m128i encodeUnorm8x4(__m128 v) {
    const __m128i rounded = _mm_cvttps_epi32(_mm_add_ps(_mm_mul_ps(v, _mm_set1_ps(255.0f)), _mm_set1_ps(0.5f)));
    const __m128i positive = _mm_castps_si128(_mm_cmpgt_ps(v, _mm_setzero_ps()));
    const __m128i full = _mm_castps_si128(_mm_cmpge_ps(v, _mm_set1_ps(1.0f)));
    return _mm_or_si128(_mm_and_si128(full, _mm_set1_epi32(255)), _mm_andnot_si128(full, _mm_and_si128(positive, rounded)));
}

// Lanes (bit i: pixel i of the 4 RGBA8 pixels at p) whose stored bytes, with the bytes a
// write mask leaves set to 0xFF in `unwritten`, are all 0xFF.
inline std::uint32_t saturatedLanes(const std::byte* p, std::uint32_t unwritten) {
    const __m128i stored = _mm_or_si128(_mm_loadu_si128(reinterpret_cast<const __m128i*>(p)),
                                        _mm_set1_epi32(int(unwritten)));
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
        if constexpr (std::is_same_v<Program, CompositeProgram> || std::is_same_v<Program, CoverageCompositeProgram>) {
            // The SSAM and SSAM+ composites as ScreenSpaceAlphaMask and the SSAM+ technique
            // draw them onto an 8-bit target, with masks of any format (compositeRow);
            // anything else takes the general path.
            compositeRow_ = !draw.capture && draw.shade && !draw.alphaTest.enabled && !draw.depthWrite &&
                            draw.colorTargetCount == 1 && isRgba8(draw.colorTargets[0]) && draw.blendNeeded[0] &&
                            isCompositeBlend(draw.blend[0]) && isRgba8(program.foliage);
        }
#if SSAM_SOFT_SSE2
        if constexpr (std::is_same_v<Program, FoliageColorProgram>)
            alphaFirst_ = !draw.capture && draw.shade && draw.alphaTest.enabled &&
                          draw.alphaTest.failMode == AlphaFailMode::Keep && program.hasAlpha4();
        if constexpr (std::is_same_v<Program, FoliageAlphaProgram>) {
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
        if constexpr (std::is_same_v<Program, CompositeProgram> || std::is_same_v<Program, WboitResolveProgram> ||
                      std::is_same_v<Program, CoverageCompositeProgram> || std::is_same_v<Program, ParticleProgram> ||
                      std::is_same_v<Program, LayerCompositeProgram> || std::is_same_v<Program, LightShaftsProgram>) {
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
        if constexpr (std::is_same_v<Program, CompositeProgram>) {
            if (compositeRow_) {
                // CompositeProgram::shade()'s alpha.
                const CompositeProgram& c = program_;
                compositeRow(bx, py, live, [&c](int x, int y) {
                    const float maxMask = texelChannel(*c.mask, x, y, 0);
                    const float addMask = c.maskAdd ? texelChannel(*c.maskAdd, x, y, 0) : texelChannel(*c.mask, x, y, 3);
                    float blend = maxMask + (addMask - maxMask) * c.params.maskLerp;
                    blend = blend > 0.0f ? (blend < 1.0f ? blend : 1.0f) : 0.0f;
                    if (c.params.squareMask) blend *= blend;
                    return blend;
                });
                return;
            }
        }
        if constexpr (std::is_same_v<Program, CoverageCompositeProgram>) {
            if (compositeRow_) {
                // CoverageCompositeProgram::shade()'s alpha.
                const CoverageCompositeProgram& c = program_;
                compositeRow(bx, py, live, [&c](int x, int y) {
                    const float maxMask = texelChannel(*c.mask, x, y, 0);
                    const float addMask = c.maskAdd ? texelChannel(*c.maskAdd, x, y, 0) : texelChannel(*c.mask, x, y, 3);
                    return layerCoverage(c.model, maxMask, addMask);
                });
                return;
            }
        }
#if SSAM_SOFT_SSE2
        if constexpr (std::is_same_v<Program, FoliageAlphaProgram>) {
            if (alphaRow_) {
                shadeAlphaRow(t, bx, py, live, centerX0, fy);
                return;
            }
        }
        if constexpr (std::is_same_v<Program, FoliageColorProgram>) {
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
        const SoftTexture& foliageTexture = *program_.foliage;
        const float* foliageTable = foliageTexture.desc.format == Format::RGBA8_SRGB ? tables.srgb : tables.unorm;
        const bool skipZero = bytesRoundTrip();
        auto byteAt = [](const std::byte* p, int c) { return std::to_integer<std::uint8_t>(p[c]); };
        for (std::uint32_t bits = live; bits; bits &= bits - 1) {
            const int px = bx + __builtin_ctz(bits);
            const float blend = factorAt(px, py);
            if (blend == 0.0f && skipZero) continue;
            const std::byte* foliage = foliageTexture.texel(0, px, py);
            std::byte* p = target.at(px, py);
            const float keep = 1.0f - blend;
            for (int c = 0; c < 3; ++c) {
                const float out = foliageTable[byteAt(foliage, c)] * blend + targetTable[byteAt(p, c)] * keep;
                p[c] = std::byte{srgbTarget ? encodeSrgb8(out) : encodeUnorm8(out)};
            }
            if (!skipZero) p[3] = std::byte{encodeUnorm8(tables.unorm[byteAt(p, 3)])};
        }
    }

#if SSAM_SOFT_SSE2
    // FoliageAlpha's row (alphaRow_): what shadeSingle does for each live lane, with the
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

    // FoliageColor's row under a Keep alpha test (alphaFirst_): the texel alpha four lanes
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

        // Alpha test in the GS sense (seeds/004): on failure the fail mode decides what
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
    bool alphaFirst_ = false;    // FoliageColor: alpha-test (Keep) on the alpha alone before shading
    // FoliageAlpha's row path (shadeAlphaRow).
    bool alphaRow_ = false;
    bool alphaZeroSkips_ = false;                       // every target ignores a zero alpha
    std::array<bool, kMaxColorTargets> oneOneBytes_{};  // blendOneOneRgba8 applies
    std::array<bool, kMaxColorTargets> oneOneHalf_{};   // blendOneOneHalf applies
    bool halfRow_ = false;                              // every target: blendOneOneHalf4 (shadeAlphaRowHalf4)
    std::array<std::uint32_t, kMaxColorTargets> unwrittenBytes_{};  // 0xFF in each byte the write mask leaves
};

}  // namespace

const SamplePattern& samplePattern(int samples) {
    static const SamplePattern k1{1, {0}, {0}};
    static const SamplePattern k2{2, {4, -4}, {4, -4}};
    static const SamplePattern k4{4, {-2, 6, -6, 2}, {-6, -2, 2, 6}};
    static const SamplePattern k8{8, {1, -1, 5, -3, -5, -7, 3, 7}, {-3, 3, 1, -5, 5, -1, 7, -7}};
    switch (samples) {
        case 2: return k2;
        case 4: return k4;
        case 8: return k8;
        default: return k1;
    }
}

void rasterizeTile(const Rect& tile, std::span<const SetupTriangle* const> triangles,
                   const std::vector<DrawState>& draws, TileCounters& counters) {
    std::size_t i = 0;
    while (i < triangles.size()) {
        // A run of triangles from one draw shares the program instance and its state.
        const std::uint32_t drawIndex = triangles[i]->drawIndex;
        std::size_t end = i + 1;
        while (end < triangles.size() && triangles[end]->drawIndex == drawIndex) ++end;
        const DrawState& draw = draws[drawIndex];
        std::visit(
            [&](const auto& program) {
                TriangleRasterizer rasterizer(draw, program, counters);
                for (std::size_t k = i; k < end; ++k) rasterizer.rasterize(*triangles[k], tile);
            },
            draw.program);
        i = end;
    }
}

void binTriangle(const SetupTriangle& t, std::uint32_t triangle, const TileGrid& grid, std::vector<BinEntry>& out) {
    if ((t.maxX - t.minX) < 2 && (t.maxY - t.minY) < 2 && grid.pattern) {
        // Tiny triangles often cover no sample: found here, while the triangle is in cache,
        // with the rasterizer's own per-sample edge test (sampleCoverage).
        const SamplePattern& pattern = *grid.pattern;
        bool any = false;
        for (int py = t.minY; py <= t.maxY && !any; ++py)
            for (int px = t.minX; px <= t.maxX && !any; ++px)
                for (int s = 0; s < pattern.count && !any; ++s) {
                    const std::int64_t x = std::int64_t(px) * kPixelStep + kHalfPixel + pattern.dx[s] * kSampleOffsetScale;
                    const std::int64_t y = std::int64_t(py) * kPixelStep + kHalfPixel + pattern.dy[s] * kSampleOffsetScale;
                    bool inside = true;
                    for (int i = 0; i < 3; ++i) inside = inside && (t.a[i] * x + t.b[i] * y + t.c[i] >= 0);
                    any = inside;
                }
        if (!any) return;
    }
    const int ts = grid.tileSize;
    const int tx0 = t.minX / ts, tx1 = t.maxX / ts, ty0 = t.minY / ts, ty1 = t.maxY / ts;
    if (tx0 == tx1 && ty0 == ty1) {  // the common small triangle: its box is in one tile
        out.push_back({std::uint32_t(ty0 * grid.tilesX + tx0), triangle});
        return;
    }
    for (int ty = ty0; ty <= ty1; ++ty) {
        const int py0 = std::max(ty * ts, t.minY), py1 = std::min(ty * ts + ts - 1, t.maxY);
        const std::int64_t ys0 = std::int64_t(py0) * kPixelStep, ys1 = std::int64_t(py1 + 1) * kPixelStep;
        for (int tx = tx0; tx <= tx1; ++tx) {
            const int px0 = std::max(tx * ts, t.minX), px1 = std::min(tx * ts + ts - 1, t.maxX);
            const std::int64_t xs0 = std::int64_t(px0) * kPixelStep, xs1 = std::int64_t(px1 + 1) * kPixelStep;
            bool reject = false;
            for (int i = 0; i < 3; ++i)
                reject = reject || t.c[i] + t.a[i] * (t.a[i] > 0 ? xs1 : xs0) + t.b[i] * (t.b[i] > 0 ? ys1 : ys0) < 0;
            if (!reject) out.push_back({std::uint32_t(ty * grid.tilesX + tx), triangle});
        }
    }
}

}  // namespace engine::render::soft
