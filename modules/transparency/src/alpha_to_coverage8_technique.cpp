// SPDX-License-Identifier: MIT
// `a2c8` and `a2c8-sharp`: alpha-to-coverage (alpha_to_coverage_technique.cpp) at 8x MSAA,
// where the backend has it. The soft backend has 8 samples; Mesa's llvmpipe (and lavapipe)
// stop at 4, so there the technique is refused when it is made, naming the backend's limit,
// instead of failing at the first frame's targets.
#include <string>

#include "alpha_to_coverage_technique.hpp"
#include "engine/core/error.hpp"
#include "engine/render/owned.hpp"
#include "technique_table.hpp"

namespace transparency::detail {

using namespace engine::render;

void requireEightSamples(Backend& backend, const char* technique) {
    constexpr int kSamples = 8;
    // The opaque targets' depth format and the colour formats a frame uses: a 1x1 target of
    // each at 8 samples, made and released at once.
    for (Format format : {Format::D32F, Format::RGBA8_SRGB, Format::RGBA16F}) {
        try {
            Owned<TextureHandle> probe(backend,
                                       backend.createTexture(renderTargetDesc("a2c8 probe", 1, 1, format, kSamples)));
        } catch (const engine::Error& e) {
            throw engine::Error(std::string(technique) + ": this backend (" + backend.name() + ") has no 8x MSAA for " +
                                std::string(formatName(format)) + ": " + e.what());
        }
    }
}

std::unique_ptr<Technique> makeAlphaToCoverage8Technique(Backend& backend, const TechniqueOptions& options) {
    requireEightSamples(backend, "a2c8");
    return makeAlphaToCoverageWith(backend, options, TechniqueKind::AlphaToCoverage8, 8, CoverageAlpha::Plain);
}

std::unique_ptr<Technique> makeAlphaToCoverage8SharpTechnique(Backend& backend, const TechniqueOptions& options) {
    requireEightSamples(backend, "a2c8-sharp");
    return makeAlphaToCoverageWith(backend, options, TechniqueKind::AlphaToCoverage8Sharp, 8, CoverageAlpha::Sharpened);
}

}  // namespace transparency::detail
