// SPDX-License-Identifier: MIT
#include "ssam/config.hpp"

#include <cmath>
#include <string>

#include "engine/core/error.hpp"

namespace ssam {

const char* maskPrecisionName(MaskPrecision precision) {
    switch (precision) {
        case MaskPrecision::RGBA8: return "rgba8";
        case MaskPrecision::RGBA16F: return "rgba16f";
        case MaskPrecision::RG16F: return "rg16f";
    }
    return "?";
}

void Config::validate() const {
    auto inUnitRange = [](const char* knob, float value) {
        if (!std::isfinite(value) || value < 0.0f || value > 1.0f)
            throw engine::Error(std::string("ssam config: ") + knob + " = " + std::to_string(value) +
                                " is outside [0, 1]");
    };
    inUnitRange("maskLerp", maskLerp);
    inUnitRange("colorAlphaReference", colorAlphaReference);
    for (int c = 0; c < 4; ++c)
        if (!std::isfinite(foliageClearColor[c]))
            throw engine::Error("ssam config: foliageClearColor has a non-finite component");
    using engine::render::CompareFunc;
    if (depthFunc == CompareFunc::Never || depthFunc == CompareFunc::Always || depthFunc == CompareFunc::Equal ||
        depthFunc == CompareFunc::NotEqual)
        throw engine::Error(std::string("ssam config: depthFunc ") + engine::render::compareFuncName(depthFunc) +
                            " cannot order surfaces (use Less/LessEqual, or Greater/GreaterEqual for reverse-Z)");
}

}  // namespace ssam
