// SPDX-License-Identifier: MIT
#pragma once
// Texel addressing shared by the general sampler (sampler.cpp) and the alpha-only one
// (alpha_sampler.hpp), so both find the same texels for the same coordinates.
#include <algorithm>
#include <cmath>

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

}  // namespace engine::render::soft
