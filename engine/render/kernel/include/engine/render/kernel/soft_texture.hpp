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
    // that are only sampled (see SoftTexture::copyDecoded); empty otherwise. The mask pass and
    // the colour pass's alpha test sample alpha alone ([Hathaway 2010] §3.5.2): with the values
    // ready, a bilinear tap pair is one 8-byte load and nothing to decode.
    std::vector<float> alpha;
    // The four channels of each such texel, decoded as the general sampler's load decodes them
    // (colour through the sRGB table for RGBA8_SRGB, byteTables()): the colour pass's filtered
    // colour reads a tap as one 16-byte load instead of four bytes and four table lookups.
    // Kept for textures of at most kDecodedCopyMaxTexels texels only (see there).
    std::vector<float> rgba;
};

// The largest texture (level 0 texels) that keeps the four-channel copy: 2048 x 2048, a 64 MiB
// copy beside 16 MiB of texels. Larger textures would spend four times their size again for a
// speed-up of the colour taps alone; they are sampled from their bytes, the same values.
inline constexpr std::size_t kDecodedCopyMaxTexels = std::size_t(2048) * 2048;

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

    // Whether copyDecoded keeps the four-channel copy for a texture of this description.
    static bool keepsFourChannelCopy(const TextureDesc& d) {
        return std::size_t(d.width) * std::size_t(d.height) <= kDecodedCopyMaxTexels;
    }

    // Fills each level's `alpha` (and `rgba`, up to kDecodedCopyMaxTexels) for a single-sampled
    // RGBA8 texture that is no render target: nothing writes such a texture after its creation,
    // so the copies never go stale. Called once its texels are final.
    void copyDecoded() {
        const bool rgba8 = desc.format == Format::RGBA8_UNORM || desc.format == Format::RGBA8_SRGB;
        if (!rgba8 || desc.samples != 1 || (desc.usage & UsageRenderTarget)) return;
        const float* unorm = byteTables().unorm;
        const float* color = desc.format == Format::RGBA8_SRGB ? byteTables().srgb : unorm;
        const bool fourChannels = keepsFourChannelCopy(desc);
        for (MipLevel& l : levels) {
            const std::size_t texels = std::size_t(l.width) * std::size_t(l.height);
            l.alpha.resize(texels);
            if (fourChannels) l.rgba.resize(4 * texels);
            for (std::size_t i = 0; i < texels; ++i) {
                auto byte = [&](int c) { return std::to_integer<std::uint8_t>(l.texels[4 * i + c]); };
                l.alpha[i] = unorm[byte(3)];
                if (!fourChannels) continue;
                for (int c = 0; c < 3; ++c) l.rgba[4 * i + c] = color[byte(c)];
                l.rgba[4 * i + 3] = l.alpha[i];
            }
        }
    }
};

}  // namespace engine::render::soft
