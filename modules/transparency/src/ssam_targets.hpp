// SPDX-License-Identifier: MIT
#pragma once
// What the SSAM and SSAM+ adapters share: SSAM's targets as the racer names its layers.
#include <vector>

#include "ssam/ssam.hpp"
#include "single_pass_technique.hpp"

namespace transparency::detail {

// The layer names: mask (or mask_max + mask_add), foliage.
inline const char* maskLayer(bool separateAdd) { return separateAdd ? "mask_max" : "mask"; }

// SSAM's targets as transients of a frame graph, in the order of ssam::Intermediates.
inline std::vector<TransientTarget> ssamTransients(const ssam::IntermediateDescs& d) {
    std::vector<TransientTarget> out{{maskLayer(d.maskAdd.has_value()), d.mask}};
    if (d.maskAdd) out.push_back({"mask_add", *d.maskAdd});
    out.push_back({"foliage", d.foliage});
    return out;
}

}  // namespace transparency::detail
