// SPDX-License-Identifier: MIT
#pragma once
// TriangleRasterizer: the class, its per-draw set-up (which fast paths apply) and the walk
// over a tile's 8x8 blocks. Its other members are defined by stage beside this file; include
// kernel/triangle_rasterizer.hpp, which brings them all.
#include <algorithm>
#include <array>
#include <concepts>
#include <cstring>
#include <type_traits>

#include "engine/render/kernel/programs.hpp"
#include "engine/render/kernel/detail/raster_support.hpp"

namespace engine::render::soft {

struct TileCounters {
    std::uint64_t pixelsShaded = 0;
    std::uint64_t pixelsTouched = 0;
    std::uint64_t depthBlocksSkipped = 0;  // DrawState::depthBounds
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

// Optionally, a composite program whose colour is not compositeColor()'s texel at the pixel but
// computed from that texture (e.g. filtered over its neighbours) gives it a block row at a time:
// compositeColorRow(bx, py, live, out) puts shade()'s colour of pixel (bx + i, py), clamped to
// [0, 1] as the 8-bit target's blend would clamp it, into out[i] for each lane i set in `live`
// and returns true, or returns false when the colour is the texel (compositeRow then reads it
// from the bytes).
template <typename Program>
constexpr bool hasCompositeColorRow() {
    return requires(const Program& p, glm::vec3* out) {
        { p.compositeColorRow(0, 0, std::uint32_t{0}, out) } -> std::same_as<bool>;
    };
}

// Optionally, a composite program gives compositeFactor of a whole block row at once:
// compositeFactorRow(bx, py, out) puts compositeFactor(bx + i, py) into out[i] for i = 0..7, the
// same bits, and returns true, or returns false where it cannot (compositeRow then asks
// compositeFactor pixel by pixel).
template <typename Program>
constexpr bool hasCompositeFactorRow() {
    return requires(const Program& p, float* out) {
        { p.compositeFactorRow(0, 0, out) } -> std::same_as<bool>;
    };
}

// Whether the program shades a block row's pixels at once (program_kernel.hpp's row hook):
// shadeRow(isa, bx, py, live, out) puts shade() of pixel (bx + i, py) into out[i] for each lane
// i set in `live`, with the same bits, in wide kernels of the draw's instruction set.
template <typename Program>
constexpr bool hasRowShader() {
    return requires(const Program& p, glm::vec4* out) { p.shadeRow(SimdIsa::Sse2, 0, 0, 0u, out); };
}

#if SOFT_RASTER_SSE2
// The row hooks below are what any program may declare (program_kernel.hpp lists them); the
// rasterizer takes a fast path for the programs that have its hooks, the built-in ones
// included, and never asks which program it is.

// Sampled rows: the texture is sampled four lanes at a time. rowSampler() is the RGBA8 sampler
// when it can be (null otherwise); shadeSampled(f, texel) is shade(f) with the texture's sample
// at f given, shadeSampled4 the same for four lanes in vectors of one channel, with the bits of
// shadeSampled lane by lane.
template <typename Program>
constexpr bool hasSampledRowHooks() {
    return requires(const Program& p, const Fragment& f, const __m128(&texel)[4], const float* const(&color)[4],
                    const float* const(&normal)[3], __m128(&out)[4]) {
        { p.rowSampler() } -> std::same_as<const AlphaSampler*>;
        { p.shadeSampled(f, glm::vec4(0.0f)) } -> std::same_as<glm::vec4>;
        p.shadeSampled4(texel, color, normal, true, out);
    };
}

// Four lanes of the alpha shade() outputs: hasAlpha4() says when alpha4 may be used, and
// alpha4(vertex alpha, u, v, duv, lanes) gives it, the same bits as shade().a.
template <typename Program>
constexpr bool hasAlpha4Hooks() {
    return requires(const Program& p, const float* in, const float* const* duv) {
        { p.hasAlpha4() } -> std::same_as<bool>;
        p.alpha4(in, in, in, duv, 0u);  // an __m128 (a vector type cannot be a concept's argument)
    };
}

// Alpha-first rows under a discarding alpha test: the sampled-row and alpha4 hooks, and
// alphaTestFactor(), the factor f for which shade().a == (f * vertex alpha) * texel alpha
// where a texture is bound (rowSampler() non-null); without one alpha4 gives the alpha.
// Only the fragments that pass are then shaded whole.
template <typename Program>
constexpr bool hasAlphaFirstHooks() {
    return hasSampledRowHooks<Program>() && hasAlpha4Hooks<Program>() && requires(const Program& p) {
        { p.alphaTestFactor() } -> std::same_as<float>;
    };
}

// Mask rows: a program whose shade() is vec4(alpha(f)), alpha(f) saturated to [0, 1] (NaN as
// 0), says so with `static constexpr bool kShadesReplicatedAlpha = true` and offers alpha(f)
// and the alpha4 hooks; the rasterizer then blends the alpha straight into ONE/ONE targets.
template <typename Program>
constexpr bool hasReplicatedAlphaHooks() {
    if constexpr (requires { Program::kShadesReplicatedAlpha; }) {
        return Program::kShadesReplicatedAlpha && hasAlpha4Hooks<Program>() &&
               requires(const Program& p, const Fragment& f) {
            { p.alpha(f) } -> std::same_as<float>;
        };
    } else {
        return false;
    }
}
#endif

// Whether the program's shade() depends on the fragment's pixel (program_kernel.hpp).
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
            depthRow_ =
                depthRowWrites_ ? depthRowFunction<true>(draw.depthFunc) : depthRowFunction<false>(draw.depthFunc);
            if (depthRowWrites_) depthOnlyBlock_ = depthOnlyBlockFunction(draw.depthFunc);
        }
        for (int i = 0; i < draw.colorTargetCount; ++i) {
            TargetView& v = color_[i];
            v = view(*draw.colorTargets[i], draw.blendNeeded[i]);
            v.rgba8Plain = v.format == Format::RGBA8_UNORM && !v.blend && draw.blend[i].writeMask == WriteAll;
            v.srgb8Plain = v.format == Format::RGBA8_SRGB && !v.blend && draw.blend[i].writeMask == WriteAll;
            v.byteLut = (v.format == Format::RGBA8_UNORM || v.format == Format::RGBA8_SRGB) && v.blend &&
                        blendIsPerChannel(draw.blend[i]);
            v.zeroKeeps = v.blend && zeroSourceKeeps(v.format, draw.blend[i]);
        }
        if constexpr (hasRowShader<Program>()) {
            rowZeroSkips_ = !draw.capture && !draw.alphaTest.enabled && !draw.depthWrite;
            for (int i = 0; i < draw.colorTargetCount; ++i)
                if (draw.blend[i].writeMask && !color_[i].zeroKeeps) rowZeroSkips_ = false;
        }
        if constexpr (hasCompositeHooks<Program>()) {
            // A mask composite (e.g. SSAM's) as such programs are drawn: onto an 8-bit target,
            // with masks of any format (compositeRow); anything else takes the general path.
            compositeRow_ = !draw.capture && draw.shade && !draw.alphaTest.enabled && !draw.depthWrite &&
                            draw.colorTargetCount == 1 && isRgba8(draw.colorTargets[0]) && draw.blendNeeded[0] &&
                            isAlphaOverKeepingAlpha(draw.blend[0]) && isRgba8(program.compositeColor());
        }
#if SOFT_RASTER_SSE2
        if constexpr (hasAlphaFirstHooks<Program>())
            alphaFirst_ = !draw.capture && draw.shade && draw.alphaTest.enabled &&
                          draw.alphaTest.failMode == AlphaFailMode::Keep && program.hasAlpha4();
        if constexpr (hasSampledRowHooks<Program>()) {
            rowSampler_ = program.rowSampler();
            sampledRow_ = !alphaFirst_ && draw.shade && rowSampler_ != nullptr;
            // One plain 8-bit target (no blend, every channel written): shadePacked4.
            packedWrite_ =
                !draw.capture && draw.colorTargetCount == 1 && (color_[0].srgb8Plain || color_[0].rgba8Plain);
        }
        if constexpr (hasReplicatedAlphaHooks<Program>()) {
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

    // coverage.hpp
    void rasterizeSingle(const SetupTriangle& t, int x0, int y0, int x1, int y1);
    void rasterizeBlock(const SetupTriangle& t, int px0, int py0, int px1, int py1);
    std::uint32_t sampleCoverage(const SetupTriangle& t, int px, int py) const;

    // shading.hpp
    void shadeRow(const SetupTriangle& t, int bx, int py, std::uint32_t mask);
    void shadeSingle(const Fragment& fragment, int px, int py, float z, std::byte* depthAt);
    void writeShaded(const glm::vec4& color, int px, int py, float z, std::byte* depthAt);
    void writeColor(int i, std::byte* p, const glm::vec4& color, std::uint8_t mask);
    void shadePixel(const SetupTriangle& t, int px, int py, std::uint32_t live);
    void storeDepth(int px, int py, std::uint32_t live, const std::array<float, 8>& z);
    Fragment interpolate(const SetupTriangle& t, int px, int py, float fx, float fy) const;

    // constant_fragment.hpp
    static bool constantPlane(const Plane& p);
    void prepareConstant(const SetupTriangle& t, int boxPixels);
    void buildBlendLut(int i, const glm::vec4& color);
    void writeConstantRow(int bx, int py, std::uint32_t live, const float* z, std::byte* depthAt);

    // fast_rows.hpp
    template <typename Factor>
    void compositeRow(int bx, int py, std::uint32_t live, const Factor& factorAt);
#if SOFT_RASTER_SSE2
    void shadeAlphaRow(const SetupTriangle& t, int bx, int py, std::uint32_t live, float centerX0, float fy);
    void shadeAlphaRow4(const SetupTriangle& t, int bx, int py, std::uint32_t live, float centerX0, float fy);
    void shadeAlphaRowHalf4(const SetupTriangle& t, int bx, int py, std::uint32_t live, float centerX0, float fy);
    __m128 alpha4(int h, std::uint32_t lanes) const;
    void shadeAlphaTestedRow(const SetupTriangle& t, int bx, int py, std::uint32_t live, float centerX0, float fy,
                             const float* z, std::byte* depthAt);
    void shadeSampledRow(const SetupTriangle& t, int bx, int py, std::uint32_t live, float centerX0, float fy,
                         const float* z, std::byte* depthAt);
    void shadeTexels(const SetupTriangle& t, const AlphaSampler::Lookup4& lookup, int bx, int py, int o,
                     std::uint32_t lanes, const float* z, std::byte* depthAt);
    void shadePacked4(const float (&texels)[4][4], bool frontFacing, int bx, int py, int o, std::uint32_t lanes,
                      const float* z, std::byte* depthAt);
    void interpolateRow(const SetupTriangle& t, float centerX0, float fy, std::uint32_t lanes);
    // What interpolateHalf computes: everything, or first what an alpha test reads (1/w, uv and
    // their derivatives, the vertex alpha), then the rest (normals, colour) for the lanes that pass.
    enum class RowInputs { All, AlphaInputs, Rest };
    void interpolateHalf(const SetupTriangle& t, float centerX0, float fy, int h, RowInputs inputs = RowInputs::All);
    Fragment rowFragment(const SetupTriangle& t, int px, int py, int i) const;
#endif

    const DrawState& draw_;
    const Program& program_;
    TileCounters& counters_;
    const SamplePattern& pattern_;
    const std::uint32_t allSamples_;
    bool single_ = false;   // one sample per pixel: the row-at-a-time path
    struct RowAttributes {  // interpolateRow's output: [component][lane]
        alignas(16) float uv[2][kBlockSize];
        alignas(16) float duv[4][kBlockSize];  // du/dx, dv/dx, du/dy, dv/dy
        alignas(16) float normal[3][kBlockSize];
        alignas(16) float color[4][kBlockSize];
        alignas(16) float w[kBlockSize];  // clip w (Fragment::clipW)
    } row_;
    int width_ = 0;  // of the pass's targets
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
    // hasRowShader: a row's (0, 0, 0, 0) colours are only counted (no alpha test, no depth
    // write, and every written target keeps what it holds under a zero source: writeColor's
    // zeroKeeps). Most of a composite layer is empty.
    bool rowZeroSkips_ = false;
    bool alphaFirst_ = false;  // hasAlphaFirstHooks: alpha-test (Keep) on the alpha alone before shading
    bool sampledRow_ = false;  // hasSampledRowHooks otherwise: the texture sampled 4 lanes at a time
    const AlphaSampler* rowSampler_ = nullptr;  // the program's rowSampler(), asked once per draw
    bool packedWrite_ = false;                  // hasSampledRowHooks onto one plain RGBA8 target: shadePacked4
    // The mask row path (shadeAlphaRow, hasReplicatedAlphaHooks).
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
