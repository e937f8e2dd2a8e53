// SPDX-License-Identifier: MIT
// Names and the list of every technique, read from the generated table (technique_table.hpp).
#include <vector>

#include "technique_table.hpp"
#include "transparency/technique.hpp"

namespace transparency {

std::span<const TechniqueKind> allTechniques() {
    static const std::vector<TechniqueKind> all = [] {
        std::vector<TechniqueKind> kinds;
        for (const detail::TechniqueRow& row : detail::techniqueTable()) kinds.push_back(row.kind);
        return kinds;
    }();
    return all;
}

const char* techniqueName(TechniqueKind kind) {
    for (const detail::TechniqueRow& row : detail::techniqueTable())
        if (row.kind == kind) return row.name;
    return "?";
}

std::optional<TechniqueKind> parseTechnique(std::string_view name) {
    for (const detail::TechniqueRow& row : detail::techniqueTable())
        if (name == row.name) return row.kind;
    return std::nullopt;
}

}  // namespace transparency
