#pragma once
// The alpha of sampleTexture<SampledChannels::AlphaOnly> for RGBA8 textures (UNORM or sRGB:
// alpha is linear in both), for the mask program (seeds/000 §3.5.2: "alpha only"). The
// mask pass shades every foliage layer, so its cost is per fragment: this sampler reads one
// byte per tap, finds each level's texels once per draw rather than per tap, and is inlined
// into the rasterizer's row loop; sample4 does four fragments at once in SSE2, and
// sampleRgba4 gives sampleTexture<All>'s four channels the same way (the alpha-tested
// colour pass). The arithmetic is the general sampler's, operation for operation (same
// addressing, floor, mix = x * (1 - a) + y * a, log2f, decode tables), so the results
// have the same bits; SIMD lanes do the same IEEE single-precision operations as scalar
// code (x86-64 SSE, no FMA contraction).
#include <array>
#include <cmath>
#include <cstdint>

#if defined(__SSE2__) && !defined(SSAM_SOFT_SCALAR)
#include <emmintrin.h>
#define SSAM_ALPHA_SAMPLER_SSE2 1
#endif

#include <glm/glm.hpp>

#include "engine/render/pixel_codec.hpp"
#include "sampler.hpp"
#include "soft_texture.hpp"
#include "texel_addressing.hpp"

namespace engine::render::soft {

class AlphaSampler {
public:
    AlphaSampler() = default;

    // Usable (valid()) for an RGBA8 texture of at most kMaxLevels levels.
    AlphaSampler(const SoftTexture& texture, const SamplerState& sampler) {
        const Format f = texture.desc.format;
        if ((f != Format::RGBA8_UNORM && f != Format::RGBA8_SRGB) || texture.levels.empty() ||
            texture.levels.size() > kMaxLevels)
            return;
        valid_ = true;
        sampler_ = sampler;
        unorm_ = byteTables().unorm;
        color_ = f == Format::RGBA8_SRGB ? byteTables().srgb : byteTables().unorm;
        stride_ = std::size_t(texture.desc.samples) * std::size_t(texture.bytesPerSample);
        last_ = static_cast<int>(texture.levels.size()) - 1;
        for (int i = 0; i <= last_; ++i) {
            const MipLevel& l = texture.levels[i];
            // Byte 3 of each texel: its alpha.
            levels_[i] = {reinterpret_cast<const std::uint8_t*>(l.texels.data()) + 3, l.width, l.height};
        }
        size0_ = glm::vec2(texture.levels[0].width, texture.levels[0].height);
        // sample4 addresses clamp-to-edge and power-of-two wrap (a mask) in SIMD.
        auto simdAddress = [&](AddressMode mode, bool width) {
            if (mode == AddressMode::Clamp) return true;
            if (mode != AddressMode::Wrap) return false;
            for (int i = 0; i <= last_; ++i) {
                const int n = width ? levels_[i].width : levels_[i].height;
                if (n & (n - 1)) return false;
            }
            return true;
        };
        simd4_ = sampler.filter != Filter::Nearest && simdAddress(sampler.addressU, true) &&
                 simdAddress(sampler.addressV, false);
    }

    bool valid() const { return valid_; }
    // sample4 may be used.
    bool simd4() const { return simd4_; }

    // sampleTexture<AlphaOnly>(texture, sampler, uv, d).a
    [[gnu::always_inline]] float sample(glm::vec2 uv, const UvDerivatives& d) const {
        switch (sampler_.filter) {
            case Filter::Nearest: return nearest(0, uv);
            case Filter::Bilinear: return bilinear(0, uv);
            case Filter::Trilinear: break;
        }
        // glm::length(v) = sqrt(v.x * v.x + v.y * v.y); std::max(a, b) = a < b ? b : a.
        const glm::vec2 sx = d.dx * size0_, sy = d.dy * size0_;
        const float lx = std::sqrt(sx.x * sx.x + sx.y * sx.y), ly = std::sqrt(sy.x * sy.x + sy.y * sy.y);
        const float rho = lx < ly ? ly : lx;
        if (!(rho > 1.0f) || last_ == 0) return bilinear(0, uv);
        const float lambda = std::log2(rho);
        if (lambda >= static_cast<float>(last_)) return bilinear(last_, uv);
        const int lo = static_cast<int>(lambda);
        const float t = lambda - lo;
        return bilinear(lo, uv) * (1.0f - t) + bilinear(lo + 1, uv) * t;
    }

#if SSAM_ALPHA_SAMPLER_SSE2
    // sample() of 4 fragments (lane i: uv (u[i], v[i]), derivatives (dudx[i], dvdx[i]) and
    // (dudy[i], dvdy[i])) into out[0..3], for the lanes set in `lanes` (others are left
    // undefined but safe to compute). Each SIMD lane does the scalar path's IEEE operations
    // in the same order; only the level choice (log2f) and the texel reads stay scalar.
    void sample4(const float* u, const float* v, const float* dudx, const float* dvdx, const float* dudy,
                 const float* dvdy, std::uint32_t lanes, float* out) const {
        const Footprint4 f = footprint4(dudx, dvdx, dudy, dvdy, lanes);
        const __m128 uu = _mm_loadu_ps(u), vv = _mm_loadu_ps(v);
        __m128 result = bilinear4(f.level0, uu, vv);
        if (f.trilinear) result = mix4(f, result, bilinear4(f.level1, uu, vv));
        _mm_storeu_ps(out, result);
    }

    // sampleTexture<SampledChannels::All> of 4 fragments as sample4 takes them, channel c of
    // lane i into out[i][c]: the sRGB colour decoded (byteTables().srgb) as the general
    // sampler's load does. The lanes' coordinates are worked out four at a time, the taps of
    // each lane filtered with its four channels in one vector (as glm's vec4 mix does).
    void sampleRgba4(const float* u, const float* v, const float* dudx, const float* dvdx, const float* dudy,
                     const float* dvdy, std::uint32_t lanes, float (*out)[4]) const {
        const Footprint4 f = footprint4(dudx, dvdx, dudy, dvdy, lanes);
        const __m128 uu = _mm_loadu_ps(u), vv = _mm_loadu_ps(v);
        __m128 result[4];
        bilinearRgba4(f.level0, uu, vv, lanes, result);
        if (f.trilinear) {
            __m128 next[4];
            bilinearRgba4(f.level1, uu, vv, std::uint32_t(f.trilinear), next);
            for (int i = 0; i < 4; ++i) {
                if (!((f.trilinear >> i) & 1)) continue;
                const __m128 t = _mm_set1_ps(f.t[i]);
                result[i] = _mm_add_ps(_mm_mul_ps(result[i], _mm_sub_ps(_mm_set1_ps(1.0f), t)), _mm_mul_ps(next[i], t));
            }
        }
        for (int i = 0; i < 4; ++i)
            if ((lanes >> i) & 1u) _mm_storeu_ps(out[i], result[i]);
    }
#endif

private:
    static constexpr std::size_t kMaxLevels = 16;
    struct Level {
        const std::uint8_t* alpha = nullptr;  // alpha byte of texel (0, 0)
        int width = 0, height = 0;
    };

    [[gnu::always_inline]] float load(const Level& l, int x, int y) const {
        return unorm_[l.alpha[(std::size_t(y) * l.width + x) * stride_]];
    }

    [[gnu::always_inline]] float nearest(int level, glm::vec2 uv) const {
        const Level& l = levels_[level];
        const int x = applyAddress(sampler_.addressU, static_cast<int>(std::floor(safeCoord(uv.x) * l.width)), l.width);
        const int y = applyAddress(sampler_.addressV, static_cast<int>(std::floor(safeCoord(uv.y) * l.height)), l.height);
        return load(l, x, y);
    }

    [[gnu::always_inline]] float bilinear(int level, glm::vec2 uv) const {
        const Level& l = levels_[level];
        const float fx = safeCoord(uv.x) * l.width - 0.5f;
        const float fy = safeCoord(uv.y) * l.height - 0.5f;
        const float x0f = std::floor(fx), y0f = std::floor(fy);
        const float ax = fx - x0f, ay = fy - y0f;
        const int x0 = static_cast<int>(x0f), y0 = static_cast<int>(y0f);
        const int xa = applyAddress(sampler_.addressU, x0, l.width), xb = applyAddress(sampler_.addressU, x0 + 1, l.width);
        const int ya = applyAddress(sampler_.addressV, y0, l.height), yb = applyAddress(sampler_.addressV, y0 + 1, l.height);
        const float top = load(l, xa, ya) * (1.0f - ax) + load(l, xb, ya) * ax;
        const float bottom = load(l, xa, yb) * (1.0f - ax) + load(l, xb, yb) * ax;
        return top * (1.0f - ay) + bottom * ay;
    }

#if SSAM_ALPHA_SAMPLER_SSE2
    // The levels each lane reads: level0 alone, or level0 and level1 mixed by t where bit i
    // of `trilinear` is set (sample()'s level choice).
    struct Footprint4 {
        alignas(16) int level0[4] = {0, 0, 0, 0};
        alignas(16) int level1[4] = {0, 0, 0, 0};
        alignas(16) float t[4] = {0.0f, 0.0f, 0.0f, 0.0f};
        int trilinear = 0;
    };
    Footprint4 footprint4(const float* dudx, const float* dvdx, const float* dudy, const float* dvdy,
                          std::uint32_t lanes) const {
        Footprint4 f;
        if (sampler_.filter != Filter::Trilinear || last_ == 0) return f;
        const __m128 w0 = _mm_set1_ps(size0_.x), h0 = _mm_set1_ps(size0_.y);
        const __m128 sxx = _mm_mul_ps(_mm_loadu_ps(dudx), w0), sxy = _mm_mul_ps(_mm_loadu_ps(dvdx), h0);
        const __m128 syx = _mm_mul_ps(_mm_loadu_ps(dudy), w0), syy = _mm_mul_ps(_mm_loadu_ps(dvdy), h0);
        const __m128 lx = _mm_sqrt_ps(_mm_add_ps(_mm_mul_ps(sxx, sxx), _mm_mul_ps(sxy, sxy)));
        const __m128 ly = _mm_sqrt_ps(_mm_add_ps(_mm_mul_ps(syx, syx), _mm_mul_ps(syy, syy)));
        const __m128 less = _mm_cmplt_ps(lx, ly);  // lx < ly ? ly : lx
        alignas(16) float rho[4];
        _mm_store_ps(rho, _mm_or_ps(_mm_and_ps(less, ly), _mm_andnot_ps(less, lx)));
        for (int i = 0; i < 4; ++i) {
            if (!((lanes >> i) & 1u) || !(rho[i] > 1.0f)) continue;
            const float lambda = std::log2(rho[i]);
            if (lambda >= static_cast<float>(last_)) {
                f.level0[i] = last_;
                continue;
            }
            const int lo = static_cast<int>(lambda);
            f.level0[i] = lo;
            f.level1[i] = lo + 1;
            f.t[i] = lambda - lo;
            f.trilinear |= 1 << i;
        }
        return f;
    }
    // mix(a, b, t) = a * (1 - t) + b * t in the trilinear lanes, a in the others.
    static __m128 mix4(const Footprint4& f, __m128 a, __m128 b) {
        const __m128 t = _mm_load_ps(f.t);
        const __m128 mixed = _mm_add_ps(_mm_mul_ps(a, _mm_sub_ps(_mm_set1_ps(1.0f), t)), _mm_mul_ps(b, t));
        const __m128i bits = _mm_setr_epi32(1, 2, 4, 8);
        const __m128 use =
            _mm_castsi128_ps(_mm_cmpeq_epi32(_mm_and_si128(_mm_set1_epi32(f.trilinear), bits), bits));
        return _mm_or_ps(_mm_and_ps(use, mixed), _mm_andnot_ps(use, a));
    }

    // safeCoord: non-finite -> 0, else clamped to [-1e6, 1e6] (min/max equal std::clamp
    // for finite values).
    static __m128 safeCoord4(__m128 v) {
        const __m128 magnitude = _mm_and_ps(v, _mm_castsi128_ps(_mm_set1_epi32(0x7FFFFFFF)));
        const __m128 finite = _mm_cmplt_ps(magnitude, _mm_set1_ps(INFINITY));  // false for NaN
        return _mm_and_ps(finite, _mm_min_ps(_mm_max_ps(v, _mm_set1_ps(-1.0e6f)), _mm_set1_ps(1.0e6f)));
    }
    // std::floor of finite values: truncation corrected downwards below 2^23, and the value
    // itself where it is already integral (which also keeps the sign of -0).
    static __m128 floor4(__m128 x) {
        const __m128 truncated = _mm_cvtepi32_ps(_mm_cvttps_epi32(x));
        const __m128 below = _mm_sub_ps(truncated, _mm_and_ps(_mm_cmpgt_ps(truncated, x), _mm_set1_ps(1.0f)));
        const __m128 magnitude = _mm_and_ps(x, _mm_castsi128_ps(_mm_set1_epi32(0x7FFFFFFF)));
        const __m128 keep = _mm_or_ps(_mm_cmpge_ps(magnitude, _mm_set1_ps(8388608.0f)), _mm_cmpeq_ps(below, x));
        return _mm_or_ps(_mm_and_ps(keep, x), _mm_andnot_ps(keep, below));
    }
    // applyAddress for Clamp (std::clamp(i, 0, last)) or power-of-two Wrap (i & last).
    static __m128i address4(AddressMode mode, __m128i i, __m128i last) {
        if (mode == AddressMode::Wrap) return _mm_and_si128(i, last);
        const __m128i low = _mm_and_si128(i, _mm_cmpgt_epi32(i, _mm_setzero_si128()));  // max(i, 0)
        const __m128i over = _mm_cmpgt_epi32(low, last);
        return _mm_or_si128(_mm_and_si128(over, last), _mm_andnot_si128(over, low));
    }
    // bilinear()'s texel coordinates and weights for lane i at level levels[i].
    struct Taps4 {
        alignas(16) int xa[4], xb[4], ya[4], yb[4];
        __m128 ax, ay;
        const Level* level[4];
    };
    Taps4 taps4(const int* levels, __m128 u, __m128 v) const {
        Taps4 taps;
        for (int i = 0; i < 4; ++i) taps.level[i] = &levels_[levels[i]];
        const __m128i width = _mm_setr_epi32(taps.level[0]->width, taps.level[1]->width, taps.level[2]->width,
                                             taps.level[3]->width);
        const __m128i height = _mm_setr_epi32(taps.level[0]->height, taps.level[1]->height, taps.level[2]->height,
                                              taps.level[3]->height);
        const __m128i one = _mm_set1_epi32(1);
        const __m128 half = _mm_set1_ps(0.5f);
        const __m128 fx = _mm_sub_ps(_mm_mul_ps(safeCoord4(u), _mm_cvtepi32_ps(width)), half);
        const __m128 fy = _mm_sub_ps(_mm_mul_ps(safeCoord4(v), _mm_cvtepi32_ps(height)), half);
        const __m128 x0f = floor4(fx), y0f = floor4(fy);
        taps.ax = _mm_sub_ps(fx, x0f);
        taps.ay = _mm_sub_ps(fy, y0f);
        const __m128i x0 = _mm_cvttps_epi32(x0f), y0 = _mm_cvttps_epi32(y0f);
        const __m128i lastX = _mm_sub_epi32(width, one), lastY = _mm_sub_epi32(height, one);
        _mm_store_si128(reinterpret_cast<__m128i*>(taps.xa), address4(sampler_.addressU, x0, lastX));
        _mm_store_si128(reinterpret_cast<__m128i*>(taps.xb), address4(sampler_.addressU, _mm_add_epi32(x0, one), lastX));
        _mm_store_si128(reinterpret_cast<__m128i*>(taps.ya), address4(sampler_.addressV, y0, lastY));
        _mm_store_si128(reinterpret_cast<__m128i*>(taps.yb), address4(sampler_.addressV, _mm_add_epi32(y0, one), lastY));
        return taps;
    }
    // bilinear() of lane i at level levels[i] (the alpha).
    __m128 bilinear4(const int* levels, __m128 u, __m128 v) const {
        const Taps4 p = taps4(levels, u, v);
        // Built in registers (not stored lane by lane and reloaded: a store-forwarding stall).
        auto tap = [&](const int* x, const int* y) {
            return _mm_setr_ps(load(*p.level[0], x[0], y[0]), load(*p.level[1], x[1], y[1]),
                               load(*p.level[2], x[2], y[2]), load(*p.level[3], x[3], y[3]));
        };
        const __m128 a = tap(p.xa, p.ya), b = tap(p.xb, p.ya), c = tap(p.xa, p.yb), d = tap(p.xb, p.yb);
        const __m128 oneF = _mm_set1_ps(1.0f);
        const __m128 rx = _mm_sub_ps(oneF, p.ax), ry = _mm_sub_ps(oneF, p.ay);
        const __m128 top = _mm_add_ps(_mm_mul_ps(a, rx), _mm_mul_ps(b, p.ax));
        const __m128 bottom = _mm_add_ps(_mm_mul_ps(c, rx), _mm_mul_ps(d, p.ax));
        return _mm_add_ps(_mm_mul_ps(top, ry), _mm_mul_ps(bottom, p.ay));
    }
    // bilinear() of lane i at level levels[i], its four channels into out[i], for the lanes
    // set in `lanes`.
    void bilinearRgba4(const int* levels, __m128 u, __m128 v, std::uint32_t lanes, __m128* out) const {
        const Taps4 p = taps4(levels, u, v);
        alignas(16) float ax[4], ay[4];
        _mm_store_ps(ax, p.ax);
        _mm_store_ps(ay, p.ay);
        const __m128 oneF = _mm_set1_ps(1.0f);
        for (int i = 0; i < 4; ++i) {
            if (!((lanes >> i) & 1u)) continue;
            const Level& l = *p.level[i];
            const __m128 wx = _mm_set1_ps(ax[i]), wy = _mm_set1_ps(ay[i]);
            const __m128 rx = _mm_sub_ps(oneF, wx), ry = _mm_sub_ps(oneF, wy);
            const __m128 top = _mm_add_ps(_mm_mul_ps(loadRgba(l, p.xa[i], p.ya[i]), rx),
                                          _mm_mul_ps(loadRgba(l, p.xb[i], p.ya[i]), wx));
            const __m128 bottom = _mm_add_ps(_mm_mul_ps(loadRgba(l, p.xa[i], p.yb[i]), rx),
                                             _mm_mul_ps(loadRgba(l, p.xb[i], p.yb[i]), wx));
            out[i] = _mm_add_ps(_mm_mul_ps(top, ry), _mm_mul_ps(bottom, wy));
        }
    }
    // The general sampler's load of an RGBA8 texel: colour through the sRGB table for sRGB.
    [[gnu::always_inline]] __m128 loadRgba(const Level& l, int x, int y) const {
        const std::uint8_t* p = l.alpha - 3 + (std::size_t(y) * l.width + x) * stride_;
        return _mm_setr_ps(color_[p[0]], color_[p[1]], color_[p[2]], unorm_[p[3]]);
    }
#endif

    bool valid_ = false;
    bool simd4_ = false;
    SamplerState sampler_;
    const float* unorm_ = nullptr;  // byteTables().unorm
    const float* color_ = nullptr;  // the table the colour channels decode through
    std::size_t stride_ = 0;        // bytes from one texel to the next
    int last_ = 0;                  // the last mip level
    glm::vec2 size0_{0.0f};         // level 0's size, as the general sampler's `size`
    std::array<Level, kMaxLevels> levels_{};
};

}  // namespace engine::render::soft
