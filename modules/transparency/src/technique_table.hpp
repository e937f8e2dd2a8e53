// SPDX-License-Identifier: MIT
#pragma once
// The technique registry as the library reads it: one row per ssam_technique() line in
// modules/transparency/CMakeLists.txt, in that order (technique_table.cpp, generated).
#include <memory>
#include <span>

#include "transparency/create_technique.hpp"

namespace transparency::detail {

// Each technique's file defines its factory, make<Kind>Technique; the generated table
// declares and points to it.
using TechniqueFactory = std::unique_ptr<Technique> (*)(engine::render::Backend& backend,
                                                        const TechniqueOptions& options);

struct TechniqueRow {
    TechniqueKind kind;
    const char* name;  // as racer --technique spells it
    TechniqueFactory make;
};

std::span<const TechniqueRow> techniqueTable();

}  // namespace transparency::detail
