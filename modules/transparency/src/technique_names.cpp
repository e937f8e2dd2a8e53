// SPDX-License-Identifier: MIT
#include <array>

#include "transparency/technique.hpp"

namespace transparency {

namespace {
constexpr std::array kAll{TechniqueKind::Ssam,          TechniqueKind::SsamPlus,     TechniqueKind::AlphaTest,
                          TechniqueKind::AlphaToCoverage, TechniqueKind::BlendUnsorted, TechniqueKind::BlendSorted,
                          TechniqueKind::Wboit,         TechniqueKind::Reference};
}  // namespace

std::span<const TechniqueKind> allTechniques() { return kAll; }

const char* techniqueName(TechniqueKind kind) {
    switch (kind) {
        case TechniqueKind::Ssam: return "ssam";
        case TechniqueKind::SsamPlus: return "ssam-plus";
        case TechniqueKind::AlphaTest: return "alpha-test";
        case TechniqueKind::AlphaToCoverage: return "a2c";
        case TechniqueKind::BlendUnsorted: return "blend-unsorted";
        case TechniqueKind::BlendSorted: return "blend-sorted";
        case TechniqueKind::Wboit: return "wboit";
        case TechniqueKind::Reference: return "reference";
    }
    return "?";
}

std::optional<TechniqueKind> parseTechnique(std::string_view name) {
    for (TechniqueKind kind : kAll)
        if (name == techniqueName(kind)) return kind;
    return std::nullopt;
}

}  // namespace transparency
