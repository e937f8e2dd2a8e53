// SPDX-License-Identifier: MIT
#include "ssam/config.hpp"

#include <cmath>
#include <string>

#include "engine/core/error.hpp"
#include "knob_rules.hpp"

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
    const float clear[4] = {foliageClearColor[0], foliageClearColor[1], foliageClearColor[2], foliageClearColor[3]};
    if (const std::string error = detail::knobError(maskLerp, colorAlphaReference, clear); !error.empty())
        throw engine::Error(error);
    using engine::render::CompareFunc;
    if (depthFunc == CompareFunc::Never || depthFunc == CompareFunc::Always || depthFunc == CompareFunc::Equal ||
        depthFunc == CompareFunc::NotEqual)
        throw engine::Error(std::string("ssam config: depthFunc ") + engine::render::compareFuncName(depthFunc) +
                            " cannot order surfaces (use Less/LessEqual, or Greater/GreaterEqual for reverse-Z)");
}

}  // namespace ssam
