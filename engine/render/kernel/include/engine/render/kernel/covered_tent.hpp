// SPDX-License-Identifier: MIT
#pragma once
// The 3x3 tent filter (1-2-1 by 1-2-1) over the covered texels of a full-screen pass's input: the
// weighted mean of the neighbours inside the texture whose alpha is above 0 (NaN is not), each
// weighted too by its alpha to the power 1.5 (alpha clamped to 1), the centre texel where none
// is, for the block rows of a kernel (program_kernel.hpp's row hooks). The input is SSAM's colour
// pass: each texel the colour of the nearest leaf that passed the alpha test, covering `alpha` of
// its pixel; a leaf's soft edge covers little of its pixel, so its colour stands for little of
// what is seen there (the exponent was measured: ssam/docs/ssam_plus.md, "The blur weighted by
// alpha"). Each texel of the 3 x (count + 2) window around a row is decoded, and its alpha weight
// taken, once instead of once per neighbour (nine times), and the sums run row by row, left to
// right, the order the GLSL loop sums them in, so a kernel's per-pixel shade() and its row give
// the same bits. The window is kept channel by channel (one array of each channel per row), so
// that filteredRow sums four pixels at once, each lane the scalar filtered()'s operations.
#include <cmath>
#include <cstddef>
#include <cstdint>

#if defined(__SSE2__) && !defined(SOFT_RASTER_SCALAR)  // as raster_support.hpp
#include <emmintrin.h>
#define SOFT_TENT_SSE2 1
#endif

#include <glm/glm.hpp>

#include "engine/render/kernel/sampler.hpp"
#include "engine/render/kernel/unorm8x4.hpp"
#include "engine/render/pixel_codec.hpp"

namespace engine::render::soft {

template <int MaxCount>
struct CoveredTentWindow {
    static constexpr int kColumns = MaxCount + 2;
    // Row `row`, column `column` of the window: texel (x0 + column - 1, y + row - 1).
    float channel[4][3][kColumns];           // r, g, b, a; 0 outside the texture
    float alphaWeight[3][kColumns];          // alpha^1.5 of a covered texel, alpha clamped to 1; else 0
    std::uint32_t coveredBits[3][kColumns];  // all ones where covered (alpha > 0), else 0

    // The texels around `count` (<= MaxCount) pixels from (x0, y): rows y - 1 .. y + 1, columns
    // x0 - 1 .. x0 + count. RGBA8 texels are decoded through the byte tables (loadTexel's values),
    // others through loadTexel.
    void load(const SoftTexture& texture, int x0, int y, int count) {
        const int width = texture.desc.width, height = texture.desc.height;
        const Format format = texture.desc.format;
        const bool bytes = format == Format::RGBA8_UNORM || format == Format::RGBA8_SRGB;
        const ByteTables& tables = byteTables();
        const float* colorTable = format == Format::RGBA8_SRGB ? tables.srgb : tables.unorm;
        for (int row = 0; row < 3; ++row) {
            const int yy = y + row - 1;
#if SOFT_TENT_SSE2
            if (bytes && texture.desc.samples == 1 && count + 2 >= 4 && x0 >= 1 && x0 + count < width && yy >= 0 &&
                yy < height) {
                loadBytesRow(row, texture.texel(0, x0 - 1, yy), count + 2, colorTable);
                continue;
            }
#endif
            for (int column = 0; column < count + 2; ++column) {
                const int x = x0 + column - 1;
                glm::vec4 t(0.0f);
                if (x >= 0 && yy >= 0 && x < width && yy < height) {
                    const std::byte* p = texture.texel(0, x, yy);
                    if (bytes) {
                        auto byteAt = [p](int c) { return std::to_integer<std::uint8_t>(p[c]); };
                        t = {colorTable[byteAt(0)], colorTable[byteAt(1)], colorTable[byteAt(2)],
                             tables.unorm[byteAt(3)]};
                    } else {
                        t = loadTexel(p, format);
                    }
                }
                for (int c = 0; c < 4; ++c) channel[c][row][column] = t[c];
                const bool covered = t.a > 0.0f;  // NaN: not covered
                const float alpha = t.a < 1.0f ? t.a : 1.0f;
                alphaWeight[row][column] = covered ? alpha * std::sqrt(alpha) : 0.0f;
                coveredBits[row][column] = covered ? ~std::uint32_t{0} : 0u;
            }
        }
    }

    glm::vec4 texel(int row, int column) const {
        return {channel[0][row][column], channel[1][row][column], channel[2][row][column], channel[3][row][column]};
    }

    // The filtered colour of the window's pixel `i` (column i + 1).
    glm::vec3 filtered(int i) const {
        glm::vec3 sum(0.0f);
        float weights = 0.0f;
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
                const int row = dy + 1, column = i + dx + 1;
                if (!coveredBits[row][column]) continue;
                const float weight = float((2 - dx * dx) * (2 - dy * dy)) * alphaWeight[row][column];
                sum += weight * glm::vec3(channel[0][row][column], channel[1][row][column], channel[2][row][column]);
                weights += weight;
            }
        return weights > 0.0f ? sum / weights : glm::vec3(texel(1, i + 1));
    }

#if SOFT_TENT_SSE2
    // load()'s row `row` where all its `columns` (>= 4) RGBA8 texels, from `texels` on, lie inside
    // the texture: the colours through the table, the alphas, coverage and weights four columns
    // at a time with load()'s operations (the alpha byte over 255 as the unorm table holds it,
    // i / 255.0f correctly rounded either way; minps(a, 1) is a < 1 ? a : 1; sqrtps rounds as
    // std::sqrt).
    void loadBytesRow(int row, const std::byte* texels, int columns, const float* colorTable) {
        for (int column = 0; column < columns; ++column) {
            const std::byte* p = texels + 4 * column;
            for (int c = 0; c < 3; ++c) channel[c][row][column] = colorTable[std::to_integer<std::uint8_t>(p[c])];
        }
        // Groups of four from column 0, the last one ending at the last column (overlapping the
        // one before where columns is no multiple of four: the same values written again).
        for (int first = 0; first < columns; first += 4) {
            const int at = first + 4 <= columns ? first : columns - 4;
            const __m128i bytes = _mm_loadu_si128(reinterpret_cast<const __m128i*>(texels + 4 * at));
            const __m128 alpha = unorm8x4(bytes, 24);
            const __m128 covered = _mm_cmpgt_ps(alpha, _mm_setzero_ps());
            const __m128 clamped = _mm_min_ps(alpha, _mm_set1_ps(1.0f));
            _mm_storeu_ps(&channel[3][row][at], alpha);
            _mm_storeu_ps(&alphaWeight[row][at], _mm_and_ps(covered, _mm_mul_ps(clamped, _mm_sqrt_ps(clamped))));
            _mm_storeu_ps(reinterpret_cast<float*>(&coveredBits[row][at]), covered);
        }
    }
#endif

    // filtered(i) of the pixels i set in `live` into out[i], four pixels per SSE2 step (pixel by
    // pixel without SSE2): lane by lane the same operations in the same order. A tap filtered() skips adds nothing here
    // either: its product is masked to +0 (coveredBits), and the sums, which start at +0 and
    // never become -0, keep their bits when +0 is added.
    void filteredRow(std::uint32_t live, glm::vec3* out) const {
        static_assert(MaxCount % 4 == 0, "whole groups of four pixels");
#if SOFT_TENT_SSE2
        for (int first = 0; first < MaxCount; first += 4) {
            if (!((live >> first) & 0xFu)) continue;
            __m128 sum[3] = {_mm_setzero_ps(), _mm_setzero_ps(), _mm_setzero_ps()};
            __m128 weights = _mm_setzero_ps();
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const int row = dy + 1, column = first + dx + 1;
                    const __m128 covered = _mm_loadu_ps(reinterpret_cast<const float*>(&coveredBits[row][column]));
                    const __m128 weight = _mm_mul_ps(_mm_set1_ps(float((2 - dx * dx) * (2 - dy * dy))),
                                                     _mm_loadu_ps(&alphaWeight[row][column]));
                    for (int c = 0; c < 3; ++c)
                        sum[c] = _mm_add_ps(
                            sum[c], _mm_and_ps(covered, _mm_mul_ps(weight, _mm_loadu_ps(&channel[c][row][column]))));
                    weights = _mm_add_ps(weights, _mm_and_ps(covered, weight));
                }
            // weights > 0 ? sum / weights : the centre texel's colour.
            const __m128 some = _mm_cmpgt_ps(weights, _mm_setzero_ps());
            alignas(16) float result[3][4];
            for (int c = 0; c < 3; ++c) {
                const __m128 centre = _mm_loadu_ps(&channel[c][1][first + 1]);
                _mm_store_ps(result[c],
                             _mm_or_ps(_mm_and_ps(some, _mm_div_ps(sum[c], weights)), _mm_andnot_ps(some, centre)));
            }
            for (std::uint32_t bits = (live >> first) & 0xFu; bits; bits &= bits - 1) {
                const int k = __builtin_ctz(bits);
                out[first + k] = {result[0][k], result[1][k], result[2][k]};
            }
        }
#else
        for (std::uint32_t bits = live; bits; bits &= bits - 1)
            out[__builtin_ctz(bits)] = filtered(__builtin_ctz(bits));
#endif
    }
};

}  // namespace engine::render::soft
