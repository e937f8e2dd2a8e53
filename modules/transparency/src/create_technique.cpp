// SPDX-License-Identifier: MIT
#include "engine/core/error.hpp"
#include "techniques.hpp"
#include "transparency/create_technique.hpp"

namespace transparency {

std::unique_ptr<Technique> createTechnique(TechniqueKind kind, engine::render::Backend& backend,
                                           const TechniqueOptions& options) {
    switch (kind) {
        case TechniqueKind::Ssam: return detail::makeSsamTechnique(backend, options);
        case TechniqueKind::AlphaTest: return detail::makeAlphaTestTechnique(backend, options);
        case TechniqueKind::AlphaToCoverage: return detail::makeAlphaToCoverageTechnique(backend, options);
        case TechniqueKind::BlendUnsorted: return detail::makeBlendUnsortedTechnique(backend, options);
        case TechniqueKind::BlendSorted: return detail::makeBlendSortedTechnique(backend, options);
        case TechniqueKind::Wboit: return detail::makeWboitTechnique(backend, options);
        case TechniqueKind::Reference: return detail::makeReferenceTechnique(backend, options);
        case TechniqueKind::SsamPlus: return detail::makeSsamPlusTechnique(backend, options);
    }
    throw engine::Error(std::string("unknown technique kind ") + std::to_string(int(kind)));
}

}  // namespace transparency
