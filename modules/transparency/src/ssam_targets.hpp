// SPDX-License-Identifier: MIT
#pragma once
// What the SSAM and SSAM+ adapters share: SSAM's targets as the racer names its layers.
#include <vector>

#include "ssam/ssam.hpp"
#include "transparency/technique.hpp"

namespace transparency::detail {

// mask (or mask_max + mask_add), foliage.
inline std::vector<NamedTarget> ssamTargets(const ssam::Intermediates& t) {
    std::vector<NamedTarget> out;
    if (t.mask) out.push_back({t.maskAdd ? "mask_max" : "mask", t.mask});
    if (t.maskAdd) out.push_back({"mask_add", t.maskAdd});
    if (t.foliage) out.push_back({"foliage", t.foliage});
    return out;
}

}  // namespace transparency::detail
