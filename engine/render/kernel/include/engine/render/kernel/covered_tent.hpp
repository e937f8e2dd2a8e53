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
// the same bits.
#include <cmath>
#include <cstddef>
#include <cstdint>

#include <glm/glm.hpp>

#include "engine/render/kernel/sampler.hpp"
#include "engine/render/pixel_codec.hpp"

namespace engine::render::soft {

template <int MaxCount>
struct CoveredTentWindow {
    glm::vec4 texel[3][MaxCount + 2];
    bool covered[3][MaxCount + 2];
    float alphaWeight[3][MaxCount + 2];  // alpha^1.5 of a covered texel, alpha clamped to 1

    // The texels around `count` (<= MaxCount) pixels from (x0, y): rows y - 1 .. y + 1, columns
    // x0 - 1 .. x0 + count. RGBA8 texels are decoded through the byte tables (loadTexel's values),
    // others through loadTexel.
    void load(const SoftTexture& texture, int x0, int y, int count) {
        const int width = texture.desc.width, height = texture.desc.height;
        const Format format = texture.desc.format;
        const bool bytes = format == Format::RGBA8_UNORM || format == Format::RGBA8_SRGB;
        const ByteTables& tables = byteTables();
        const float* colorTable = format == Format::RGBA8_SRGB ? tables.srgb : tables.unorm;
        for (int row = 0; row < 3; ++row)
            for (int column = 0; column < count + 2; ++column) {
                const int x = x0 + column - 1, yy = y + row - 1;
                glm::vec4& t = texel[row][column];
                if (x < 0 || yy < 0 || x >= width || yy >= height) {
                    t = glm::vec4(0.0f);
                    covered[row][column] = false;
                    alphaWeight[row][column] = 0.0f;
                    continue;
                }
                const std::byte* p = texture.texel(0, x, yy);
                if (bytes) {
                    auto byteAt = [p](int c) { return std::to_integer<std::uint8_t>(p[c]); };
                    t = {colorTable[byteAt(0)], colorTable[byteAt(1)], colorTable[byteAt(2)], tables.unorm[byteAt(3)]};
                } else {
                    t = loadTexel(p, format);
                }
                covered[row][column] = t.a > 0.0f;  // NaN: not covered
                const float alpha = t.a < 1.0f ? t.a : 1.0f;
                alphaWeight[row][column] = covered[row][column] ? alpha * std::sqrt(alpha) : 0.0f;
            }
    }

    // The filtered colour of the window's pixel `i` (column i + 1).
    glm::vec3 filtered(int i) const {
        glm::vec3 sum(0.0f);
        float weights = 0.0f;
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
                if (!covered[dy + 1][i + dx + 1]) continue;
                const float weight = float((2 - dx * dx) * (2 - dy * dy)) * alphaWeight[dy + 1][i + dx + 1];
                sum += weight * glm::vec3(texel[dy + 1][i + dx + 1]);
                weights += weight;
            }
        return weights > 0.0f ? sum / weights : glm::vec3(texel[1][i + 1]);
    }
};

}  // namespace engine::render::soft
