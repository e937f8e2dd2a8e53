// SPDX-License-Identifier: MIT
#pragma once
// Texture sampling as GL does it: nearest (GL_NEAREST), bilinear (GL_LINEAR, level 0)
// and trilinear (GL_LINEAR_MIPMAP_LINEAR, lambda from the analytic UV derivatives);
// wrap, clamp-to-edge and mirrored-repeat addressing. Non-finite coordinates sample
// texel (0,0) rather than reaching undefined float-to-int conversions.
#include <cstdint>
#include <cstring>

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

// fetchTexel(t, x, y)[c] (loadTexel's channel c), with the formats SSAM's masks come in
// read without decoding the other channels: RGBA8_UNORM through the table, half floats
// through decodeHalf (a channel the format lacks takes loadTexel's default).
inline float texelChannel(const SoftTexture& t, int x, int y, int c) {
    const std::byte* p = t.texel(0, x, y);
    std::uint16_t half;
    switch (t.desc.format) {
        case Format::RGBA8_UNORM: return byteTables().unorm[std::to_integer<std::uint8_t>(p[c])];
        case Format::R16F:
        case Format::RG16F:
        case Format::RGBA16F: {
            const int channels = t.desc.format == Format::R16F ? 1 : t.desc.format == Format::RG16F ? 2 : 4;
            if (c >= channels) break;
            std::memcpy(&half, p + 2 * c, sizeof half);
            return decodeHalf(half);
        }
        default: break;
    }
    return loadTexel(p, t.desc.format)[c];
}

// Mip level `level` (>= 1) computed as the 2x2 box average of level - 1 (in linear light).
void generateMipLevel(SoftTexture& texture, int level);

}  // namespace engine::render::soft
