// SPDX-License-Identifier: MIT
#pragma once
// A technique followed by the temporal pass (transparency/temporal.hpp): `hashed+taa`,
// `alpha-test+taa` are each one of these around their technique.
#include <memory>

#include "single_pass_technique.hpp"
#include "transparency/create_technique.hpp"

namespace transparency::detail {

// Alpha testing as the temporal pass wraps it (alpha_test_technique.cpp).
std::unique_ptr<SinglePassTechnique> makeAlphaTestPass(engine::render::Backend& backend,
                                                       const TechniqueOptions& options);

// `inner`'s frame, then the temporal pass, in one frame-graph pass named after `kind`.
std::unique_ptr<Technique> makeTemporalTechnique(engine::render::Backend& backend, const TechniqueOptions& options,
                                                 TechniqueKind kind, std::unique_ptr<SinglePassTechnique> inner);

}  // namespace transparency::detail
