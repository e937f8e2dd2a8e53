// SPDX-License-Identifier: MIT
#pragma once
// How every SSAM message writes a number it refuses: "nan", "inf", "-inf", or std::to_string's
// fixed notation (the value the host gave, to six decimals).
#include <cmath>
#include <string>

namespace ssam::core {

inline std::string numberText(float value) {
    if (std::isnan(value)) return "nan";
    if (std::isinf(value)) return value > 0.0f ? "inf" : "-inf";
    return std::to_string(value);
}

}  // namespace ssam::core
