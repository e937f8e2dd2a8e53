// SPDX-License-Identifier: MIT
#pragma once
// The hashed alpha-test technique with its per-frame seed on (hashed+taa: the threshold
// changes every frame, FoliageFrame::frameIndex) or off (`hashed`: the same every frame).
#include <memory>

#include "single_pass_technique.hpp"
#include "transparency/create_technique.hpp"

namespace transparency::detail {

std::unique_ptr<SinglePassTechnique> makeHashedTechniqueFor(engine::render::Backend& backend,
                                                            const TechniqueOptions& options, bool seedPerFrame);

}  // namespace transparency::detail
