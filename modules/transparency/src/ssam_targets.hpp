// SPDX-License-Identifier: MIT
#pragma once
// What the SSAM and SSAM+ adapters share: SSAM's targets as the racer names its layers.
#include <vector>

#include "ssam/ssam.hpp"
#include "transparency/technique.hpp"

namespace transparency::detail {

// The layer names: mask (or mask_max + mask_add), foliage.
inline const char* maskLayer(bool separateAdd) { return separateAdd ? "mask_max" : "mask"; }

inline std::vector<NamedTarget> ssamTargets(const ssam::Intermediates& t) {
    std::vector<NamedTarget> out;
    if (t.mask) out.push_back({maskLayer(bool(t.maskAdd)), t.mask});
    if (t.maskAdd) out.push_back({"mask_add", t.maskAdd});
    if (t.foliage) out.push_back({"foliage", t.foliage});
    return out;
}

// SSAM's targets as transients of a frame graph, in the order of ssam::Intermediates.
inline std::vector<TransientTarget> ssamTransients(const ssam::IntermediateDescs& d) {
    std::vector<TransientTarget> out{{maskLayer(d.maskAdd.has_value()), d.mask}};
    if (d.maskAdd) out.push_back({"mask_add", *d.maskAdd});
    out.push_back({"foliage", d.foliage});
    return out;
}

}  // namespace transparency::detail
