// SPDX-License-Identifier: MIT
#include "engine/core/error.hpp"
#include "ssam/ssam.hpp"
#include "technique_table.hpp"
#include "transparency/create_technique.hpp"

namespace transparency {

ssam::Settings ssamSettings(const TechniqueOptions& options) {
    const std::optional<ssam::DepthTest> test = ssam::depthTestOf(options.depthFunc);
    if (!test)
        throw engine::Error(std::string("technique options: depthFunc ") +
                            engine::render::compareFuncName(options.depthFunc) +
                            " cannot order surfaces (use Less/LessEqual, or Greater/GreaterEqual for reverse-Z)");
    ssam::Settings settings = options.ssam;
    settings.depthTest = *test;
    return settings;
}

std::unique_ptr<Technique> createTechnique(TechniqueKind kind, engine::render::Backend& backend,
                                           const TechniqueOptions& options) {
    for (const detail::TechniqueRow& row : detail::techniqueTable())
        if (row.kind == kind) return row.make(backend, options);
    throw engine::Error(std::string("unknown technique kind ") + std::to_string(int(kind)));
}

}  // namespace transparency
