#include "tile_rasterizer.hpp"

#include <algorithm>
#include <cstring>

#include "blend.hpp"
#include "pixel_codec.hpp"

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

template <typename Program>
class TriangleRasterizer {
public:
    TriangleRasterizer(const DrawState& draw, const Program& program, TileCounters& counters)
        : draw_(draw), program_(program), counters_(counters), pattern_(*draw.pattern),
          allSamples_((1u << draw.samples) - 1u) {}

    void rasterize(const SetupTriangle& t, const Rect& tile) {
        const int x0 = std::max(tile.x, t.minX), x1 = std::min(tile.x + tile.width - 1, t.maxX);
        const int y0 = std::max(tile.y, t.minY), y1 = std::min(tile.y + tile.height - 1, t.maxY);
        if (x0 > x1 || y0 > y1) return;
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
        if constexpr (needs.uv || needs.normal || needs.color) {
            const float inverseW = evaluate(t.inverseW, fx, fy);
            const float w = 1.0f / inverseW;
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
        }
        return f;
    }

    const DrawState& draw_;
    const Program& program_;
    TileCounters& counters_;
    const SamplePattern& pattern_;
    const std::uint32_t allSamples_;
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

void rasterizeTile(const Rect& tile, std::span<const std::uint32_t> indices, const std::vector<SetupTriangle>& triangles,
                   const std::vector<DrawState>& draws, TileCounters& counters) {
    std::size_t i = 0;
    while (i < indices.size()) {
        // A run of triangles from one draw shares the program instance and its state.
        const std::uint32_t drawIndex = triangles[indices[i]].drawIndex;
        std::size_t end = i + 1;
        while (end < indices.size() && triangles[indices[end]].drawIndex == drawIndex) ++end;
        const DrawState& draw = draws[drawIndex];
        std::visit(
            [&](const auto& program) {
                TriangleRasterizer rasterizer(draw, program, counters);
                for (std::size_t k = i; k < end; ++k) rasterizer.rasterize(triangles[indices[k]], tile);
            },
            draw.program);
        i = end;
    }
}

}  // namespace engine::render::soft
