// SPDX-License-Identifier: MIT
// `ssam+taa`: SSAM with the paper's defaults; then the temporal pass (transparency/temporal.hpp, temporal_technique.cpp).
#include "technique_table.hpp"
#include "temporal_technique.hpp"

namespace transparency::detail {

std::unique_ptr<Technique> makeSsamTaaTechnique(engine::render::Backend& backend, const TechniqueOptions& options) {
    return makeTemporalTechnique(backend, options, TechniqueKind::SsamTaa, makeSsamTechnique(backend, options));
}

}  // namespace transparency::detail
