// SPDX-License-Identifier: MIT
#pragma once
// The ranges of the paper's knobs, shared by ssam::Config::validate() and ssam::gl's Settings so
// both entry points accept the same values. Header-only and free of engine types: ssam_gl links
// nothing of the engine (its package component needs no engine dependency).
#include <cmath>
#include <string>

namespace ssam::detail {

// "" when the knobs are usable, else what is wrong, naming the knob ("ssam config: ...").
inline std::string knobError(float maskLerp, float colorAlphaReference, const float foliageClearColor[4]) {
    auto outside = [](const char* knob, float value) {
        return std::string("ssam config: ") + knob + " = " + std::to_string(value) + " is outside [0, 1]";
    };
    // §3.5.4: a lerp weight; §3.5.3: an alpha reference. Both in [0, 1] and finite.
    if (!std::isfinite(maskLerp) || maskLerp < 0.0f || maskLerp > 1.0f) return outside("maskLerp", maskLerp);
    if (!std::isfinite(colorAlphaReference) || colorAlphaReference < 0.0f || colorAlphaReference > 1.0f)
        return outside("colorAlphaReference", colorAlphaReference);
    for (int c = 0; c < 4; ++c)
        if (!std::isfinite(foliageClearColor[c])) return "ssam config: foliageClearColor has a non-finite component";
    return {};
}

}  // namespace ssam::detail
