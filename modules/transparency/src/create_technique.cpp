#include "engine/core/error.hpp"
#include "techniques.hpp"
#include "transparency/technique.hpp"

namespace transparency {

std::unique_ptr<Technique> createTechnique(TechniqueKind kind, engine::render::Backend& backend,
                                           const TechniqueOptions& options) {
    switch (kind) {
        case TechniqueKind::Ssam: return detail::makeSsamTechnique(backend, options);
        case TechniqueKind::AlphaTest: return detail::makeAlphaTestTechnique(backend, options);
        default: break;
    }
    throw engine::Error(std::string("technique '") + techniqueName(kind) + "' is not implemented yet");
}

}  // namespace transparency
