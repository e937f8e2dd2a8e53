// SPDX-License-Identifier: MIT
#pragma once
// Alpha-to-coverage at a given sample count, plain or sharpened: `a2c`, `a2c8`, `a2c-sharp` and
// `a2c8-sharp` share it.
#include <memory>

#include "transparency/create_technique.hpp"

namespace transparency::detail {

// The alpha that becomes coverage: the surface's, or [Golus 2017]'s sharpened by its screen-space
// derivative (transparency/sharpened_coverage.hpp).
enum class CoverageAlpha { Plain, Sharpened };

std::unique_ptr<Technique> makeAlphaToCoverageWith(engine::render::Backend& backend, const TechniqueOptions& options,
                                                   TechniqueKind kind, int samples, CoverageAlpha alpha);

// Throws, naming `technique` and the format, where the backend has no 8x MSAA for the targets
// a frame at 8 samples uses (Mesa's llvmpipe and lavapipe stop at 4).
void requireEightSamples(engine::render::Backend& backend, const char* technique);

}  // namespace transparency::detail
