#include "engine/core/error.hpp"
#include "transparency/technique.hpp"

namespace transparency {

// Placeholder until each technique lands (modules/transparency issue): refuses clearly.
std::unique_ptr<Technique> createTechnique(TechniqueKind kind, engine::render::Backend&, const TechniqueOptions&) {
    throw engine::Error(std::string("technique '") + techniqueName(kind) + "' is not implemented yet");
}

}  // namespace transparency
