// SPDX-License-Identifier: MIT
#pragma once
// A technique followed by the temporal pass (transparency/temporal.hpp): `hashed+taa`,
// `alpha-test+taa` are each one of these around their technique.
#include <memory>

#include "transparency/create_technique.hpp"

namespace transparency::detail {

// The factories of the techniques wrapped (defined in their own files, declared for the
// generated table in technique_table.cpp).
std::unique_ptr<Technique> makeAlphaTestTechnique(engine::render::Backend& backend, const TechniqueOptions& options);

std::unique_ptr<Technique> makeTemporalTechnique(engine::render::Backend& backend, const TechniqueOptions& options,
                                                 TechniqueKind kind, std::unique_ptr<Technique> inner);

}  // namespace transparency::detail
