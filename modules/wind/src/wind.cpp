// SPDX-License-Identifier: MIT
#include "wind/wind.hpp"

#include <cmath>
#include <string>

#include "engine/core/error.hpp"

namespace wind {

void validate(const Wind& w) {
    auto check = [](float v, const char* field) {
        if (!std::isfinite(v)) throw engine::Error(std::string("Wind.") + field + " is not finite");
        if (v < 0.0f) throw engine::Error(std::string("Wind.") + field + " = " + std::to_string(v) + " is negative");
    };
    for (int i = 0; i < 3; ++i)
        if (!std::isfinite(w.direction[i])) throw engine::Error("Wind.direction is not finite");
    if (!(std::abs(w.direction.x) + std::abs(w.direction.z) > 0.0f))
        throw engine::Error("Wind.direction has no horizontal component");
    check(w.strength, "strength");
    check(w.swayFrequency, "swayFrequency");
    check(w.gustStrength, "gustStrength");
    check(w.gustFrequency, "gustFrequency");
    check(w.gustWavelength, "gustWavelength");
    check(w.flutterAmplitude, "flutterAmplitude");
    check(w.flutterFrequency, "flutterFrequency");
    check(w.activeRadius, "activeRadius");
    check(w.springRate, "springRate");
    check(w.colliderMargin, "colliderMargin");
    if (!(w.gustWavelength > 0.0f)) throw engine::Error("Wind.gustWavelength must be positive");
}

}  // namespace wind
