// SPDX-License-Identifier: MIT
#pragma once
// Alpha-to-coverage at a given sample count: `a2c` (4) and `a2c8` (8) share it.
#include <memory>

#include "transparency/create_technique.hpp"

namespace transparency::detail {

std::unique_ptr<Technique> makeAlphaToCoverageWith(engine::render::Backend& backend, const TechniqueOptions& options,
                                                   TechniqueKind kind, int samples);

}  // namespace transparency::detail
