// SPDX-License-Identifier: MIT
#include "engine/core/error.hpp"
#include "technique_table.hpp"
#include "transparency/create_technique.hpp"

namespace transparency {

std::unique_ptr<Technique> createTechnique(TechniqueKind kind, engine::render::Backend& backend,
                                           const TechniqueOptions& options) {
    for (const detail::TechniqueRow& row : detail::techniqueTable())
        if (row.kind == kind) return row.make(backend, options);
    throw engine::Error(std::string("unknown technique kind ") + std::to_string(int(kind)));
}

}  // namespace transparency
