// SPDX-License-Identifier: MIT
#pragma once
// The alpha of sampleTexture<SampledChannels::AlphaOnly> for RGBA8 textures (UNORM or sRGB:
// alpha is linear in both), for the mask program ([Hathaway 2010] §3.5.2: "alpha only"). The
// mask pass shades every foliage layer, so its cost is per fragment: this sampler reads the
// texture's decoded alpha copy (MipLevel::alpha) where it has one, finds each level's
// texels once per draw rather than per tap, and is inlined into the rasterizer's row loop;
// lookup4 + alpha4 do four fragments at once in SSE2, and rgba4 gives sampleTexture<All>'s
// four channels the same way (the alpha-tested colour pass, after its alpha test). The
// arithmetic is the general sampler's, operation for operation (same addressing, floor,
// mix = x * (1 - a) + y * a, textureLambda, decoded values), so the results have the same bits;
// SIMD lanes do the same IEEE single-precision operations as scalar code (x86-64 SSE, no
// FMA contraction).
#include <array>
#include <cmath>
#include <cstdint>

#if defined(__SSE2__) && !defined(SOFT_RASTER_SCALAR)
#include <emmintrin.h>
#define SOFT_SAMPLER_SSE2 1
#endif

#include <glm/glm.hpp>

#include "engine/render/pixel_codec.hpp"
#include "sampler.hpp"
#include "soft_texture.hpp"
#include "detail/texture_lod.hpp"
#include "detail/texel_addressing.hpp"

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
        bool decoded = true;
        for (int i = 0; i <= last_; ++i) {
            const MipLevel& l = texture.levels[i];
            decoded = decoded && !l.alpha.empty();
            levels_[i] = {reinterpret_cast<const std::uint8_t*>(l.texels.data()),
                          l.alpha.empty() ? nullptr : l.alpha.data(), l.rgba.empty() ? nullptr : l.rgba.data(), l.width,
                          l.height};
        }
        size0_ = glm::vec2(texture.levels[0].width, texture.levels[0].height);
        // lookup4 addresses clamp-to-edge and power-of-two wrap (a mask) in SIMD, and reads
        // the decoded alpha copy.
        auto simdAddress = [&](AddressMode mode, bool width) {
            if (mode == AddressMode::Clamp) return true;
            if (mode != AddressMode::Wrap) return false;
            for (int i = 0; i <= last_; ++i) {
                const int n = width ? levels_[i].width : levels_[i].height;
                if (n & (n - 1)) return false;
            }
            return true;
        };
        simd4_ = decoded && sampler.filter != Filter::Nearest && simdAddress(sampler.addressU, true) &&
                 simdAddress(sampler.addressV, false);
    }

    bool valid() const { return valid_; }
    // lookup4, alpha4 and rgba4 may be used.
    bool simd4() const { return simd4_; }

    // sampleTexture<AlphaOnly>(texture, sampler, uv, d).a
    [[gnu::always_inline]] float sample(glm::vec2 uv, const UvDerivatives& d) const {
        switch (sampler_.filter) {
            case Filter::Nearest: return nearest(0, uv);
            case Filter::Bilinear: return bilinear(0, uv);
            case Filter::Trilinear: break;
        }
        // glm::dot(v, v) = v.x * v.x + v.y * v.y; std::max(a, b) = a < b ? b : a.
        const glm::vec2 sx = d.dx * size0_, sy = d.dy * size0_;
        const float lx = sx.x * sx.x + sx.y * sx.y, ly = sy.x * sy.x + sy.y * sy.y;
        const float rhoSquared = lx < ly ? ly : lx;
        if (!(rhoSquared > 1.0f) || last_ == 0) return bilinear(0, uv);
        const float lambda = textureLambda(rhoSquared);
        if (lambda >= static_cast<float>(last_)) return bilinear(last_, uv);
        const int lo = static_cast<int>(lambda);
        const float t = lambda - lo;
        return bilinear(lo, uv) * (1.0f - t) + bilinear(lo + 1, uv) * t;
    }

#if SOFT_SAMPLER_SSE2
    // What sampling 4 fragments reads: each lane's level(s) and the texels and weights of
    // bilinear() there (lane i: uv (u[i], v[i]), derivatives (dudx[i], dvdx[i]) and (dudy[i],
    // dvdy[i])), for the lanes set in `lanes` (the others read safe, unused texels). Worked
    // out once for both alpha4() and rgba4(), so the colour pass can alpha-test first and
    // filter the colour of the fragments that pass only.
    struct Lookup4;
    [[gnu::always_inline]] Lookup4 lookup4(const float* u, const float* v, const float* dudx, const float* dvdx,
                                           const float* dudy, const float* dvdy, std::uint32_t lanes) const;

    // sample() of the 4 lanes. Each SIMD lane does the scalar path's IEEE operations in the
    // same order; only the texel reads stay scalar.
    [[gnu::always_inline]] __m128 alpha4(const Lookup4& lookup) const;
    // sampleTexture<SampledChannels::All> of the lanes set in `lanes`, channel c of lane i
    // into out[i][c]: the sRGB colour decoded (byteTables().srgb) as the general sampler's
    // load does; each lane's taps filtered with its four channels in one vector (as glm's
    // vec4 mix does).
    void rgba4(const Lookup4& lookup, std::uint32_t lanes, float (*out)[4]) const;
#endif

private:
    static constexpr std::size_t kMaxLevels = 16;
    struct Level {
        const std::uint8_t* rgba = nullptr;  // texel (0, 0)
        const float* alpha = nullptr;        // its decoded alpha (MipLevel::alpha), if the texture has them
        const float* decoded = nullptr;      // its four decoded channels (MipLevel::rgba), likewise
        int width = 0, height = 0;
    };

    [[gnu::always_inline]] float load(const Level& l, int x, int y) const {
        return unorm_[l.rgba[(std::size_t(y) * l.width + x) * stride_ + 3]];
    }

    [[gnu::always_inline]] float nearest(int level, glm::vec2 uv) const {
        const Level& l = levels_[level];
        const int x = applyAddress(sampler_.addressU, static_cast<int>(std::floor(safeCoord(uv.x) * l.width)), l.width);
        const int y =
            applyAddress(sampler_.addressV, static_cast<int>(std::floor(safeCoord(uv.y) * l.height)), l.height);
        return load(l, x, y);
    }

    [[gnu::always_inline]] float bilinear(int level, glm::vec2 uv) const {
        const Level& l = levels_[level];
        const BilinearTaps b = bilinearTaps(sampler_, l.width, l.height, uv);
        const float top = load(l, b.xa, b.ya) * (1.0f - b.ax) + load(l, b.xb, b.ya) * b.ax;
        const float bottom = load(l, b.xa, b.yb) * (1.0f - b.ax) + load(l, b.xb, b.yb) * b.ax;
        return top * (1.0f - b.ay) + bottom * b.ay;
    }

#if SOFT_SAMPLER_SSE2
    // The levels each lane reads: level0 alone, or level0 and level1 mixed by t where bit i
    // of `trilinear` is set (sample()'s level choice).
    struct Footprint4 {
        alignas(16) int level0[4] = {0, 0, 0, 0};
        alignas(16) int level1[4] = {0, 0, 0, 0};
        alignas(16) float t[4] = {0.0f, 0.0f, 0.0f, 0.0f};
        int trilinear = 0;
    };
    // bilinear()'s texel coordinates (addressed) and weights for lane i at level levels[i].
    struct Taps4 {
        __m128i xa, xb, ya, yb;
        __m128i width;  // of each lane's level
        __m128 ax, ay;
        const Level* level[4];
    };

public:
    struct Lookup4 {
        Footprint4 footprint;
        Taps4 level0, level1;  // level1: where footprint.trilinear != 0
    };

private:
    [[gnu::always_inline]] Footprint4 footprint4(const float* dudx, const float* dvdx, const float* dudy,
                                                 const float* dvdy, std::uint32_t lanes) const {
        Footprint4 f;
        if (sampler_.filter != Filter::Trilinear || last_ == 0) return f;
        const __m128 w0 = _mm_set1_ps(size0_.x), h0 = _mm_set1_ps(size0_.y);
        const __m128 sxx = _mm_mul_ps(_mm_loadu_ps(dudx), w0), sxy = _mm_mul_ps(_mm_loadu_ps(dvdx), h0);
        const __m128 syx = _mm_mul_ps(_mm_loadu_ps(dudy), w0), syy = _mm_mul_ps(_mm_loadu_ps(dvdy), h0);
        const __m128 lx = _mm_add_ps(_mm_mul_ps(sxx, sxx), _mm_mul_ps(sxy, sxy));
        const __m128 ly = _mm_add_ps(_mm_mul_ps(syx, syx), _mm_mul_ps(syy, syy));
        const __m128 less = _mm_cmplt_ps(lx, ly);  // lx < ly ? ly : lx
        const __m128 rhoSquared = _mm_or_ps(_mm_and_ps(less, ly), _mm_andnot_ps(less, lx));
        // The lanes that minify (rho^2 > 1, false for NaN) take lambda = textureLambda(rho^2);
        // the other lanes of l are masked off below.
        const std::uint32_t minified =
            lanes & std::uint32_t(_mm_movemask_ps(_mm_cmpgt_ps(rhoSquared, _mm_set1_ps(1.0f))));
        if (!minified) return f;
        // Per lane: lambda >= last reads the last level alone; else levels lo and lo + 1 mixed
        // by t = lambda - lo, lo = int(lambda) (truncation, lambda > 0).
        const __m128 l = textureLambda4(rhoSquared);
        const __m128i bits = _mm_setr_epi32(1, 2, 4, 8);
        const __m128i inMinified = _mm_cmpeq_epi32(_mm_and_si128(_mm_set1_epi32(int(minified)), bits), bits);
        const __m128i beyond = _mm_and_si128(inMinified, _mm_castps_si128(_mm_cmpge_ps(l, _mm_set1_ps(float(last_)))));
        const __m128i mixed = _mm_andnot_si128(beyond, inMinified);
        const __m128i lo = _mm_cvttps_epi32(l);
        _mm_store_si128(reinterpret_cast<__m128i*>(f.level0),
                        _mm_or_si128(_mm_and_si128(beyond, _mm_set1_epi32(last_)), _mm_and_si128(mixed, lo)));
        _mm_store_si128(reinterpret_cast<__m128i*>(f.level1),
                        _mm_and_si128(mixed, _mm_add_epi32(lo, _mm_set1_epi32(1))));
        _mm_store_ps(f.t, _mm_and_ps(_mm_castsi128_ps(mixed), _mm_sub_ps(l, _mm_cvtepi32_ps(lo))));
        f.trilinear = _mm_movemask_ps(_mm_castsi128_ps(mixed));
        return f;
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
    [[gnu::always_inline]] Taps4 taps4(const int* levels, __m128 u, __m128 v) const {
        Taps4 taps;
        for (int i = 0; i < 4; ++i) taps.level[i] = &levels_[levels[i]];
        taps.width =
            _mm_setr_epi32(taps.level[0]->width, taps.level[1]->width, taps.level[2]->width, taps.level[3]->width);
        const __m128i height =
            _mm_setr_epi32(taps.level[0]->height, taps.level[1]->height, taps.level[2]->height, taps.level[3]->height);
        const __m128i one = _mm_set1_epi32(1);
        const __m128 half = _mm_set1_ps(0.5f);
        const __m128 fx = _mm_sub_ps(_mm_mul_ps(safeCoord4(u), _mm_cvtepi32_ps(taps.width)), half);
        const __m128 fy = _mm_sub_ps(_mm_mul_ps(safeCoord4(v), _mm_cvtepi32_ps(height)), half);
        const __m128 x0f = floor4(fx), y0f = floor4(fy);
        taps.ax = _mm_sub_ps(fx, x0f);
        taps.ay = _mm_sub_ps(fy, y0f);
        const __m128i x0 = _mm_cvttps_epi32(x0f), y0 = _mm_cvttps_epi32(y0f);
        const __m128i lastX = _mm_sub_epi32(taps.width, one), lastY = _mm_sub_epi32(height, one);
        taps.xa = address4(sampler_.addressU, x0, lastX);
        taps.xb = address4(sampler_.addressU, _mm_add_epi32(x0, one), lastX);
        taps.ya = address4(sampler_.addressV, y0, lastY);
        taps.yb = address4(sampler_.addressV, _mm_add_epi32(y0, one), lastY);
        return taps;
    }
    // The alphas of bilinear()'s four taps (a, b on row ya; c, d on row yb) from the decoded
    // copy. Inside the level (xb = xa + 1 in every lane, the usual case) one 8-byte load
    // reads both taps of a row.
    [[gnu::always_inline]] void alphaTaps4(const Taps4& p, __m128& a, __m128& b, __m128& c, __m128& d) const {
        // Texel index y * width + x per lane: madd_epi16 multiplies the low 16-bit halves
        // (y < 2^14 and width <= 2^14 after addressing; the high halves are 0) exactly.
        alignas(16) int top[4], bottom[4], step[4];
        _mm_store_si128(reinterpret_cast<__m128i*>(top), _mm_add_epi32(_mm_madd_epi16(p.ya, p.width), p.xa));
        _mm_store_si128(reinterpret_cast<__m128i*>(bottom), _mm_add_epi32(_mm_madd_epi16(p.yb, p.width), p.xa));
        const __m128i dx = _mm_sub_epi32(p.xb, p.xa);
        // Lanes i and j of one row as (tap at xa, tap at xb) pairs: (a_i, b_i, a_j, b_j).
        auto pairs = [&](const int* at, int i, int j) {
            const float* pi = p.level[i]->alpha + at[i];
            const float* pj = p.level[j]->alpha + at[j];
            return _mm_loadh_pi(_mm_castsi128_ps(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(pi))),
                                reinterpret_cast<const __m64*>(pj));
        };
        auto apart = [&](const int* at, int i, int j) {  // a clamped or wrapped edge: xb is xa, or 0
            const float* pi = p.level[i]->alpha + at[i];
            const float* pj = p.level[j]->alpha + at[j];
            return _mm_setr_ps(pi[0], pi[step[i]], pj[0], pj[step[j]]);
        };
        __m128 top01, top23, bottom01, bottom23;
        if (_mm_movemask_epi8(_mm_cmpeq_epi32(dx, _mm_set1_epi32(1))) == 0xFFFF) {
            top01 = pairs(top, 0, 1), top23 = pairs(top, 2, 3);
            bottom01 = pairs(bottom, 0, 1), bottom23 = pairs(bottom, 2, 3);
        } else {
            _mm_store_si128(reinterpret_cast<__m128i*>(step), dx);
            top01 = apart(top, 0, 1), top23 = apart(top, 2, 3);
            bottom01 = apart(bottom, 0, 1), bottom23 = apart(bottom, 2, 3);
        }
        a = _mm_shuffle_ps(top01, top23, _MM_SHUFFLE(2, 0, 2, 0));
        b = _mm_shuffle_ps(top01, top23, _MM_SHUFFLE(3, 1, 3, 1));
        c = _mm_shuffle_ps(bottom01, bottom23, _MM_SHUFFLE(2, 0, 2, 0));
        d = _mm_shuffle_ps(bottom01, bottom23, _MM_SHUFFLE(3, 1, 3, 1));
    }
    // bilinear() of lane i at the taps' level (the alpha).
    [[gnu::always_inline]] __m128 bilinear4(const Taps4& p) const {
        __m128 a, b, c, d;
        alphaTaps4(p, a, b, c, d);
        const __m128 oneF = _mm_set1_ps(1.0f);
        const __m128 rx = _mm_sub_ps(oneF, p.ax), ry = _mm_sub_ps(oneF, p.ay);
        const __m128 top = _mm_add_ps(_mm_mul_ps(a, rx), _mm_mul_ps(b, p.ax));
        const __m128 bottom = _mm_add_ps(_mm_mul_ps(c, rx), _mm_mul_ps(d, p.ax));
        return _mm_add_ps(_mm_mul_ps(top, ry), _mm_mul_ps(bottom, p.ay));
    }
    // bilinear() of lane i at the taps' level, its four channels into out[i], for the lanes
    // set in `lanes`.
    void bilinearRgba4(const Taps4& p, std::uint32_t lanes, __m128* out) const {
        alignas(16) int xa[4], xb[4], ya[4], yb[4];
        alignas(16) float ax[4], ay[4];
        _mm_store_si128(reinterpret_cast<__m128i*>(xa), p.xa);
        _mm_store_si128(reinterpret_cast<__m128i*>(xb), p.xb);
        _mm_store_si128(reinterpret_cast<__m128i*>(ya), p.ya);
        _mm_store_si128(reinterpret_cast<__m128i*>(yb), p.yb);
        _mm_store_ps(ax, p.ax);
        _mm_store_ps(ay, p.ay);
        const __m128 oneF = _mm_set1_ps(1.0f);
        for (int i = 0; i < 4; ++i) {
            if (!((lanes >> i) & 1u)) continue;
            const Level& l = *p.level[i];
            const __m128 wx = _mm_set1_ps(ax[i]), wy = _mm_set1_ps(ay[i]);
            const __m128 rx = _mm_sub_ps(oneF, wx), ry = _mm_sub_ps(oneF, wy);
            const __m128 top =
                _mm_add_ps(_mm_mul_ps(loadRgba(l, xa[i], ya[i]), rx), _mm_mul_ps(loadRgba(l, xb[i], ya[i]), wx));
            const __m128 bottom =
                _mm_add_ps(_mm_mul_ps(loadRgba(l, xa[i], yb[i]), rx), _mm_mul_ps(loadRgba(l, xb[i], yb[i]), wx));
            out[i] = _mm_add_ps(_mm_mul_ps(top, ry), _mm_mul_ps(bottom, wy));
        }
    }
    // The general sampler's load of an RGBA8 texel: colour through the sRGB table for sRGB;
    // the decoded copy holds those values.
    [[gnu::always_inline]] __m128 loadRgba(const Level& l, int x, int y) const {
        if (l.decoded) return _mm_loadu_ps(l.decoded + 4 * (std::size_t(y) * l.width + x));
        const std::uint8_t* p = l.rgba + (std::size_t(y) * l.width + x) * stride_;
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

#if SOFT_SAMPLER_SSE2
inline AlphaSampler::Lookup4 AlphaSampler::lookup4(const float* u, const float* v, const float* dudx, const float* dvdx,
                                                   const float* dudy, const float* dvdy, std::uint32_t lanes) const {
    Lookup4 l;
    l.footprint = footprint4(dudx, dvdx, dudy, dvdy, lanes);
    const __m128 uu = _mm_loadu_ps(u), vv = _mm_loadu_ps(v);
    l.level0 = taps4(l.footprint.level0, uu, vv);
    if (l.footprint.trilinear) l.level1 = taps4(l.footprint.level1, uu, vv);
    return l;
}

inline __m128 AlphaSampler::alpha4(const Lookup4& l) const {
    const __m128 a = bilinear4(l.level0);
    if (!l.footprint.trilinear) return a;
    // mix(a, b, t) = a * (1 - t) + b * t in the trilinear lanes, a in the others.
    const __m128 b = bilinear4(l.level1);
    const __m128 t = _mm_load_ps(l.footprint.t);
    const __m128 mixed = _mm_add_ps(_mm_mul_ps(a, _mm_sub_ps(_mm_set1_ps(1.0f), t)), _mm_mul_ps(b, t));
    const __m128i bits = _mm_setr_epi32(1, 2, 4, 8);
    const __m128 use =
        _mm_castsi128_ps(_mm_cmpeq_epi32(_mm_and_si128(_mm_set1_epi32(l.footprint.trilinear), bits), bits));
    return _mm_or_ps(_mm_and_ps(use, mixed), _mm_andnot_ps(use, a));
}

inline void AlphaSampler::rgba4(const Lookup4& l, std::uint32_t lanes, float (*out)[4]) const {
    __m128 result[4];
    bilinearRgba4(l.level0, lanes, result);
    if (const std::uint32_t trilinear = lanes & std::uint32_t(l.footprint.trilinear)) {
        __m128 next[4];
        bilinearRgba4(l.level1, trilinear, next);
        for (int i = 0; i < 4; ++i) {
            if (!((trilinear >> i) & 1u)) continue;
            const __m128 t = _mm_set1_ps(l.footprint.t[i]);
            result[i] = _mm_add_ps(_mm_mul_ps(result[i], _mm_sub_ps(_mm_set1_ps(1.0f), t)), _mm_mul_ps(next[i], t));
        }
    }
    for (int i = 0; i < 4; ++i)
        if ((lanes >> i) & 1u) _mm_storeu_ps(out[i], result[i]);
}
#endif

}  // namespace engine::render::soft
