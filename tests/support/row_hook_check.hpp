// SPDX-License-Identifier: MIT
#pragma once
// Checks a soft-backend program's row hooks (shadeRow, engine/render/kernel/program_kernel.hpp;
// compositeColorRow, the composite fast path's colours) against its per-pixel shade(), bit for
// bit, over every block row of an image.
#include <bit>
#include <cstdint>

#include <gtest/gtest.h>
#include <glm/glm.hpp>

#include "engine/render/kernel/fragment.hpp"
#include "engine/render/kernel/simd_isa.hpp"
#include "lcg.hpp"

namespace ssam::testing {

// kernel.shadeRow(isa, bx, y, live, out) for every 8-pixel block row of a width x height
// image, `live` the row's pixels inside the image with random gaps in every third row, each
// live lane compared with kernel.shade() of that pixel; seen(shade's result) for each.
// The live lanes of the 8-pixel block row at (bx, y) of a `width`-wide image: the row's pixels
// inside the image, with random gaps in every third row.
inline std::uint32_t liveLanes(int bx, int y, int width, Lcg& rng) {
    std::uint32_t live = bx + 8 <= width ? 0xFFu : (1u << (width - bx)) - 1u;
    if ((y + bx) % 3 == 0) live &= std::uint32_t(rng.unit() * 256.0f);  // gaps in the row
    return live;
}

// Every 8-pixel block row of a width x height image: row(bx, y, live, out) fills out[i] for each
// live lane (liveLanes) and returns true (false: it gave nothing), each live lane's first
// `Channels` channels compared with kernel.shade() of that pixel; seen(shade's result) for each.
template <int Channels, typename Kernel, typename Row, typename Seen>
::testing::AssertionResult rowMatchesShade(const Kernel& kernel, int width, int height, Lcg& rng, const char* what,
                                           Row row, Seen seen) {
    for (int y = 0; y < height; ++y) {
        for (int bx = 0; bx < width; bx += 8) {
            const std::uint32_t live = liveLanes(bx, y, width, rng);
            glm::vec<Channels, float> out[8];
            if (!row(bx, y, live, out)) return ::testing::AssertionFailure() << what << " gave nothing at row " << y;
            for (int i = 0; i < 8; ++i) {
                if (!((live >> i) & 1u)) continue;
                engine::render::soft::Fragment f;
                f.x = bx + i;
                f.y = y;
                const glm::vec4 expected = kernel.shade(f);
                seen(expected);
                for (int c = 0; c < Channels; ++c)
                    if (std::bit_cast<std::uint32_t>(out[i][c]) != std::bit_cast<std::uint32_t>(expected[c]))
                        return ::testing::AssertionFailure()
                               << what << ", pixel (" << bx + i << ", " << y << "), channel " << c << ": " << out[i][c]
                               << " != " << expected[c];
            }
        }
    }
    return ::testing::AssertionSuccess();
}

// kernel.shadeRow(isa, ...) for every block row against shade(), all four channels.
template <typename Kernel, typename Seen>
::testing::AssertionResult rowHookMatchesShade(const Kernel& kernel, engine::render::soft::SimdIsa isa, int width,
                                               int height, Lcg& rng, Seen seen) {
    return rowMatchesShade<4>(
        kernel, width, height, rng, engine::render::soft::simdIsaName(isa),
        [&](int bx, int y, std::uint32_t live, glm::vec4* out) {
            kernel.shadeRow(isa, bx, y, live, out);
            return true;
        },
        seen);
}

// kernel.compositeColorRow(...) for every block row against shade()'s colour; fails where the
// kernel says its colour is the texel's (returns false).
template <typename Kernel>
::testing::AssertionResult compositeColorRowMatchesShade(const Kernel& kernel, int width, int height, Lcg& rng) {
    return rowMatchesShade<3>(
        kernel, width, height, rng, "compositeColorRow",
        [&](int bx, int y, std::uint32_t live, glm::vec3* out) { return kernel.compositeColorRow(bx, y, live, out); },
        [](const glm::vec4&) {});
}

}  // namespace ssam::testing
