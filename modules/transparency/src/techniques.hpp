// SPDX-License-Identifier: MIT
#pragma once
// The factories behind createTechnique, one per file (modules/transparency/src/*_technique.cpp).
#include <memory>

#include "transparency/create_technique.hpp"

namespace transparency::detail {

std::unique_ptr<Technique> makeSsamTechnique(engine::render::Backend& backend, const TechniqueOptions& options);
std::unique_ptr<Technique> makeAlphaTestTechnique(engine::render::Backend& backend, const TechniqueOptions& options);

std::unique_ptr<Technique> makeAlphaToCoverageTechnique(engine::render::Backend& backend,
                                                        const TechniqueOptions& options);
std::unique_ptr<Technique> makeBlendUnsortedTechnique(engine::render::Backend& backend, const TechniqueOptions& options);
std::unique_ptr<Technique> makeBlendSortedTechnique(engine::render::Backend& backend, const TechniqueOptions& options);
std::unique_ptr<Technique> makeWboitTechnique(engine::render::Backend& backend, const TechniqueOptions& options);
std::unique_ptr<Technique> makeReferenceTechnique(engine::render::Backend& backend, const TechniqueOptions& options);
std::unique_ptr<Technique> makeSsamPlusTechnique(engine::render::Backend& backend, const TechniqueOptions& options);

}  // namespace transparency::detail
