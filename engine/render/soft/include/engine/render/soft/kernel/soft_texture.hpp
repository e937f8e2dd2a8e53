// SPDX-License-Identifier: MIT
#pragma once
// Storage of one texture or render target: native texels per mip level, samples of a
// pixel stored next to each other so a resolve or a blend touches one cache line.
#include <cstddef>
#include <vector>

#include "engine/render/pixel_codec.hpp"
#include "engine/render/texture.hpp"

namespace engine::render::soft {

struct MipLevel {
    int width = 0;
    int height = 0;
    std::vector<std::byte> texels;
    // The alpha of each RGBA8 texel, decoded (byteTables().unorm: code / 255), for textures
    // that are only sampled (see SoftTexture::copyAlpha); empty otherwise. The mask pass and
    // the colour pass's alpha test sample alpha alone ([Hathaway 2010] §3.5.2): with the values
    // ready, a bilinear tap pair is one 8-byte load and nothing to decode.
    std::vector<float> alpha;
};

struct SoftTexture {
    TextureDesc desc;
    int bytesPerSample = 0;
    std::vector<MipLevel> levels;

    std::byte* sample(int x, int y, int s) {
        const MipLevel& l = levels[0];
        return levels[0].texels.data() + ((std::size_t(y) * l.width + x) * desc.samples + s) * bytesPerSample;
    }
    const std::byte* texel(int level, int x, int y) const {
        const MipLevel& l = levels[level];
        return l.texels.data() + (std::size_t(y) * l.width + x) * desc.samples * bytesPerSample;
    }

    // Fills each level's `alpha` for a single-sampled RGBA8 texture that is no render target:
    // nothing writes such a texture after its creation, so the copy never goes stale. Called
    // once its texels are final.
    void copyAlpha() {
        const bool rgba8 = desc.format == Format::RGBA8_UNORM || desc.format == Format::RGBA8_SRGB;
        if (!rgba8 || desc.samples != 1 || (desc.usage & UsageRenderTarget)) return;
        for (MipLevel& l : levels) {
            l.alpha.resize(std::size_t(l.width) * std::size_t(l.height));
            for (std::size_t i = 0; i < l.alpha.size(); ++i)
                l.alpha[i] = byteTables().unorm[std::to_integer<std::uint8_t>(l.texels[4 * i + 3])];
        }
    }
};

}  // namespace engine::render::soft
