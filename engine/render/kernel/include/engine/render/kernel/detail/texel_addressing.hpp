// SPDX-License-Identifier: MIT
#pragma once
// Texel addressing shared by the general sampler (sampler.cpp) and the alpha-only one
// (alpha_sampler.hpp), so both find the same texels for the same coordinates.
#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>

#include "engine/render/texture.hpp"

namespace engine::render::soft {

// Forced inline: called per texel in the samplers' inner loops.
[[gnu::always_inline]] inline int applyAddress(AddressMode mode, int i, int size) {
    // Power-of-two sizes (the usual case) take a mask instead of a division: i & (n - 1)
    // is the non-negative i mod n that the remainder-and-fix-up below computes.
    const bool powerOfTwo = (size & (size - 1)) == 0;
    switch (mode) {
        case AddressMode::Wrap: {
            if (powerOfTwo) return i & (size - 1);
            const int m = i % size;
            return m < 0 ? m + size : m;
        }
        case AddressMode::Clamp: return std::clamp(i, 0, size - 1);
        case AddressMode::Mirror: {
            // GL mirrored repeat: period 2*size, second half reflected.
            int m;
            if (powerOfTwo) {
                m = i & (2 * size - 1);
            } else {
                m = i % (2 * size);
                if (m < 0) m += 2 * size;
            }
            return m < size ? m : 2 * size - 1 - m;
        }
    }
    return 0;
}

// Bounds the coordinate so the int conversion is defined; far-away texels wrap to the
// same place anyway after addressing.
inline float safeCoord(float v) {
    if (!std::isfinite(v)) return 0.0f;
    return std::clamp(v, -1.0e6f, 1.0e6f);
}

// The 2x2 texels bilinear filtering reads at uv in a width x height level (columns xa, xb,
// rows ya, yb, addressed) and the weights ax, ay of the second column and row.
struct BilinearTaps {
    int xa, xb, ya, yb;
    float ax, ay;
};

[[gnu::always_inline]] inline BilinearTaps bilinearTaps(const SamplerState& s, int width, int height, glm::vec2 uv) {
    const float fx = safeCoord(uv.x) * width - 0.5f;
    const float fy = safeCoord(uv.y) * height - 0.5f;
    const float x0f = std::floor(fx), y0f = std::floor(fy);
    const int x0 = static_cast<int>(x0f), y0 = static_cast<int>(y0f);
    return {applyAddress(s.addressU, x0, width),
            applyAddress(s.addressU, x0 + 1, width),
            applyAddress(s.addressV, y0, height),
            applyAddress(s.addressV, y0 + 1, height),
            fx - x0f,
            fy - y0f};
}

}  // namespace engine::render::soft
