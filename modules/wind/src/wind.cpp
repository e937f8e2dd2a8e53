// SPDX-License-Identifier: MIT
#include "wind/wind.hpp"

#include <cmath>
#include <string>

#include "engine/core/error.hpp"
#include "engine/core/field_checks.hpp"

namespace wind {

void validate(const Wind& w) {
    const engine::FieldChecks check{"Wind"};
    for (int i = 0; i < 3; ++i)
        if (!std::isfinite(w.direction[i])) throw engine::Error("Wind.direction is not finite");
    if (!(std::abs(w.direction.x) + std::abs(w.direction.z) > 0.0f))
        throw engine::Error("Wind.direction has no horizontal component");
    check.nonNegative(w.strength, "strength");
    check.nonNegative(w.swayFrequency, "swayFrequency");
    check.nonNegative(w.gustStrength, "gustStrength");
    check.nonNegative(w.gustFrequency, "gustFrequency");
    check.positive(w.gustWavelength, "gustWavelength");
    check.nonNegative(w.flutterAmplitude, "flutterAmplitude");
    check.nonNegative(w.flutterFrequency, "flutterFrequency");
    check.nonNegative(w.activeRadius, "activeRadius");
    check.nonNegative(w.springRate, "springRate");
    check.nonNegative(w.colliderMargin, "colliderMargin");
}

}  // namespace wind
