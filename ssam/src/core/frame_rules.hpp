// SPDX-License-Identifier: MIT
#pragma once
// What ssam::gl and ssam::vk check of a frame's numbers before using them, shared so both entry
// points refuse the same values with the same words. Header-only and free of engine and API
// types (the core's): each entry point passes its FrameDesc's arrays and field names.
#include <cmath>
#include <cstddef>
#include <string>

#include "number_text.hpp"

namespace ssam::detail {

// "" when every element is finite, else "<field>[i] is <value>": a NaN or an infinity in the
// view-projection would reach the bounds' screen rectangle and every vertex (NaN positions draw
// nothing, or anything, depending on the device).
inline std::string matrixError(const float m[16], const char* field) {
    for (int i = 0; i < 16; ++i)
        if (!std::isfinite(m[i]))
            return std::string(field) + "[" + std::to_string(i) + "] is " + core::numberText(m[i]) + " (not finite)";
    return {};
}

// "" when a world box can hold what the host draws: finite corners, min <= max on each axis, and
// an extent in at least two axes. A box flat in one axis (a card in a plane) is fine; one flat in
// two or three (a line or a point, e.g. a Box left at its default) holds no triangle that could
// cover a pixel, so it can only be a mistake, and would scissor the composite to nothing.
inline std::string boxError(const float min[3], const float max[3], const std::string& field) {
    static const char* const axis[3] = {"x", "y", "z"};
    for (int a = 0; a < 3; ++a)
        if (!std::isfinite(min[a]) || !std::isfinite(max[a]))
            return field + " " + axis[a] + " is [" + core::numberText(min[a]) + ", " + core::numberText(max[a]) +
                   "] (not finite)";
    for (int a = 0; a < 3; ++a)
        if (max[a] < min[a])
            return field + " has max." + axis[a] + " " + core::numberText(max[a]) + " below min." + axis[a] + " " +
                   core::numberText(min[a]) + " (a negative size)";
    int flat = 0;
    for (int a = 0; a < 3; ++a) flat += max[a] == min[a] ? 1 : 0;
    if (flat >= 2)
        return field + " has zero size in " + std::to_string(flat) +
               " axes (a line or a point holds nothing that covers a pixel; a Box left at its default?)";
    return {};
}

}  // namespace ssam::detail
