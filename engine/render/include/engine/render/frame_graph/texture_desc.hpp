// SPDX-License-Identifier: MIT
#pragma once
// What the frame graph knows about a texture: just enough to allocate one. The render
// backend owns the real texture descriptor and format enum; the graph sits below it and
// must not include it, so the format travels as an opaque integer that only the
// allocator callback interprets.
#include <cstdint>

namespace engine::render {

struct FrameGraphTextureDesc {
    std::uint32_t width = 1;
    std::uint32_t height = 1;
    std::uint32_t format = 0;   // the backend's format enumerator, cast to an integer
    std::uint32_t samples = 1;  // MSAA sample count; 1 = single-sampled

    bool operator==(const FrameGraphTextureDesc&) const = default;
};

}  // namespace engine::render
