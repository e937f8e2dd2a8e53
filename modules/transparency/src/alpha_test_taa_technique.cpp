// SPDX-License-Identifier: MIT
// `alpha-test+taa`: alpha testing at the material's cutoff; the jitter moves the cut edges, the history averages them; then the temporal pass (transparency/temporal.hpp, temporal_technique.cpp).
#include "technique_table.hpp"
#include "temporal_technique.hpp"

namespace transparency::detail {

std::unique_ptr<Technique> makeAlphaTestTaaTechnique(engine::render::Backend& backend,
                                                     const TechniqueOptions& options) {
    return makeTemporalTechnique(backend, options, TechniqueKind::AlphaTestTaa, makeAlphaTestPass(backend, options));
}

}  // namespace transparency::detail
