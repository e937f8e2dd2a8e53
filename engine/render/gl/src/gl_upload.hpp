// SPDX-License-Identifier: MIT
#pragma once
// The levels a texture's upload writes (the GL and GLES drivers share it): each given level in
// its stored layout, and every level beyond them generated on the CPU with the soft backend's
// rounding, so that mips are bit-identical to its own.
#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

#include "gl_api.hpp"

#include "engine/render/texel_codec.hpp"
#include "engine/render/texture.hpp"

namespace engine::render::gl {

// Sets the unpack state to tightly packed rows from client memory, then calls
// write(level, width, height, storedBytes) for each level of `desc`.
template <typename Write>
void uploadLevels(const TextureDesc& desc, const TextureData& data, Write&& write) {
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
    glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
    std::vector<std::byte> previous;
    int previousWidth = 0, previousHeight = 0;
    for (int level = 0; level < desc.mipLevels; ++level) {
        const int w = std::max(1, desc.width >> level), h = std::max(1, desc.height >> level);
        std::vector<std::byte> stored = std::size_t(level) < data.levels.size()
                                            ? toStored(desc.format, data.levels[level], std::size_t(w) * h)
                                            : generateMip(desc.format, previous, previousWidth, previousHeight, w, h);
        write(level, w, h, stored.data());
        previous = std::move(stored);
        previousWidth = w, previousHeight = h;
    }
}

}  // namespace engine::render::gl
