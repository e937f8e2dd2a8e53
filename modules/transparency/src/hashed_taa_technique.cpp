// SPDX-License-Identifier: MIT
// `hashed+taa`: hashed alpha testing with its threshold changed every frame, so that the history averages it; then the temporal pass (transparency/temporal.hpp, temporal_technique.cpp).
#include "hashed_technique.hpp"
#include "technique_table.hpp"
#include "temporal_technique.hpp"

namespace transparency::detail {

std::unique_ptr<Technique> makeHashedTaaTechnique(engine::render::Backend& backend, const TechniqueOptions& options) {
    return makeTemporalTechnique(backend, options, TechniqueKind::HashedTaa,
                                 makeHashedTechniqueFor(backend, options, /*seedPerFrame=*/true));
}

}  // namespace transparency::detail
