#pragma once
// Storage of one texture or render target: native texels per mip level, samples of a
// pixel stored next to each other so a resolve or a blend touches one cache line.
#include <cstddef>
#include <vector>

#include "engine/render/texture.hpp"

namespace engine::render::soft {

struct MipLevel {
    int width = 0;
    int height = 0;
    std::vector<std::byte> texels;
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
};

}  // namespace engine::render::soft
