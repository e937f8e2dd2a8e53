// SPDX-License-Identifier: MIT
#pragma once
// Mipmap chains for textures, filtered the way [Hargreaves 2009] says filtering is correct:
// on premultiplied colour, in linear light. Alpha-tested foliage additionally keeps its
// alpha-test coverage down the chain (Castaño, "Computing Alpha Mipmaps", 2010): plain
// box filtering averages thin leaves into alpha below the cutoff, so distant trees go bald.
#include <vector>

#include "engine/assets/image.hpp"
#include "engine/render/texture.hpp"

namespace engine::assets {

struct MipOptions {
    // Alpha mode of the returned levels. Filtering always happens on premultiplied values;
    // Straight output divides the colour back out (colour is 0 where alpha is 0).
    render::AlphaMode output = render::AlphaMode::Premultiplied;
    // In (0, 1]: scale each level's alpha so that the fraction of texels with alpha >= cutoff
    // matches level 0's. Any other value (the default -1): no coverage preservation.
    float preserveCoverageCutoff = -1.0f;
    int maxLevels = 0;  // 0: the full chain down to 1x1
};

// Level 0 is `level0` converted to options.output; level i+1 is the 2x2 box filter of level i
// (clamped at odd edges), computed in float from the unscaled previous level so rounding and
// coverage scaling never accumulate. Input may be straight or premultiplied, sRGB or linear
// (the image says which); every level keeps `srgb`. Throws engine::Error for an empty image.
std::vector<RgbaImage> generateMips(const RgbaImage& level0, const MipOptions& options = {});

// generateMips with preserveCoverageCutoff = cutoff: the chain for an alpha-tested
// (glTF alphaMode MASK) texture. Throws engine::Error unless 0 < cutoff <= 1.
std::vector<RgbaImage> generateCoveragePreservingMips(const RgbaImage& level0, float cutoff,
                                                      render::AlphaMode output = render::AlphaMode::Premultiplied);

// Fraction of texels whose alpha (code / 255) is >= cutoff: what an alpha test at `cutoff`
// keeps (glTF MASK: "fully opaque if alpha >= alphaCutoff").
float alphaCoverage(const RgbaImage& image, float cutoff);

// The levels' bytes as the render interface takes them (spans into `levels`).
render::TextureData textureData(const std::vector<RgbaImage>& levels);

}  // namespace engine::assets
