// SPDX-License-Identifier: MIT
#pragma once
// Checks a soft-backend program's row hook (shadeRow, engine/render/kernel/program_kernel.hpp)
// against its per-pixel shade(), bit for bit, over every block row of an image.
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
template <typename Kernel, typename Seen>
::testing::AssertionResult rowHookMatchesShade(const Kernel& kernel, engine::render::soft::SimdIsa isa, int width,
                                               int height, Lcg& rng, Seen seen) {
    for (int y = 0; y < height; ++y) {
        for (int bx = 0; bx < width; bx += 8) {
            std::uint32_t live = bx + 8 <= width ? 0xFFu : (1u << (width - bx)) - 1u;
            if ((y + bx) % 3 == 0) live &= std::uint32_t(rng.unit() * 256.0f);  // gaps in the row
            glm::vec4 out[8];
            kernel.shadeRow(isa, bx, y, live, out);
            for (int i = 0; i < 8; ++i) {
                if (!((live >> i) & 1u)) continue;
                engine::render::soft::Fragment f;
                f.x = bx + i;
                f.y = y;
                const glm::vec4 expected = kernel.shade(f);
                seen(expected);
                for (int c = 0; c < 4; ++c)
                    if (std::bit_cast<std::uint32_t>(out[i][c]) != std::bit_cast<std::uint32_t>(expected[c]))
                        return ::testing::AssertionFailure()
                               << engine::render::soft::simdIsaName(isa) << ", pixel (" << bx + i << ", " << y
                               << "), channel " << c << ": " << out[i][c] << " != " << expected[c];
            }
        }
    }
    return ::testing::AssertionSuccess();
}

}  // namespace ssam::testing
