// SPDX-License-Identifier: MIT
#pragma once
// Texture sampling as GL does it: nearest (GL_NEAREST), bilinear (GL_LINEAR, level 0)
// and trilinear (GL_LINEAR_MIPMAP_LINEAR, lambda from the analytic UV derivatives);
// wrap, clamp-to-edge and mirrored-repeat addressing. Non-finite coordinates sample
// texel (0,0) rather than reaching undefined float-to-int conversions.
#include <glm/glm.hpp>

#include "engine/render/pixel_codec.hpp"
#include "soft_texture.hpp"

namespace engine::render::soft {

enum class SampledChannels { All, AlphaOnly };

struct UvDerivatives {
    glm::vec2 dx{0.0f};
    glm::vec2 dy{0.0f};
};

template <SampledChannels Channels = SampledChannels::All>
glm::vec4 sampleTexture(const SoftTexture& texture, const SamplerState& sampler, glm::vec2 uv,
                        const UvDerivatives& derivatives);

// Texel (x, y) of level 0, sample 0; for full-screen passes that read one texel per pixel.
inline glm::vec4 fetchTexel(const SoftTexture& texture, int x, int y) {
    return loadTexel(texture.texel(0, x, y), texture.desc.format);
}

// Mip level `level` (>= 1) computed as the 2x2 box average of level - 1 (in linear light).
void generateMipLevel(SoftTexture& texture, int level);

}  // namespace engine::render::soft
