// SPDX-License-Identifier: MIT
#pragma once
// CPU textures built in memory for tests of soft-backend program kernels (no backend needed).
#include <cstddef>
#include <cstring>
#include <vector>

#include "engine/render/kernel/soft_texture.hpp"

namespace ssam::testing {

// One level of width x height texels of `bytesPerTexel` zero bytes each.
inline engine::render::soft::SoftTexture softImage(int width, int height, engine::render::Format format,
                                                   int bytesPerTexel) {
    engine::render::soft::SoftTexture t;
    t.desc.width = width;
    t.desc.height = height;
    t.desc.format = format;
    t.bytesPerSample = bytesPerTexel;
    t.levels.push_back({width,
                        height,
                        std::vector<std::byte>(std::size_t(width) * std::size_t(height) * std::size_t(bytesPerTexel)),
                        {},
                        {}});
    return t;
}

// A D32F image whose texel i (row-major) holds depthAt(i).
template <typename DepthAt>
engine::render::soft::SoftTexture depthImage(int width, int height, DepthAt depthAt) {
    engine::render::soft::SoftTexture t = softImage(width, height, engine::render::Format::D32F, 4);
    for (int i = 0; i < width * height; ++i) {
        const float z = depthAt(i);
        std::memcpy(t.levels[0].texels.data() + 4 * std::size_t(i), &z, 4);
    }
    return t;
}

}  // namespace ssam::testing
