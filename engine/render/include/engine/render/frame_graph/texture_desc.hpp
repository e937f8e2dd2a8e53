// SPDX-License-Identifier: MIT
#pragma once
// What the frame graph knows about a texture: just enough to allocate one. The render
// backend owns the real texture descriptor and format enum; the graph sits below it and
// must not include it, so the format (and how its alpha is stored) travel as opaque
// integers that only the allocator callback interprets.
#include <cstdint>

namespace engine::render {

struct FrameGraphTextureDesc {
    std::uint32_t width = 1;
    std::uint32_t height = 1;
    std::uint32_t format = 0;   // the backend's format enumerator, cast to an integer
    std::uint32_t samples = 1;  // MSAA sample count; 1 = single-sampled
    std::uint32_t alpha = 0;    // the backend's alpha mode (straight or premultiplied texels), as an integer

    bool operator==(const FrameGraphTextureDesc&) const = default;
};

// A transient sized relative to the frame: `frame`'s size divided by `divisor`, rounded up
// (a half-resolution layer covers an odd last row and column too), in `format`.
inline FrameGraphTextureDesc relativeTo(const FrameGraphTextureDesc& frame, std::uint32_t format,
                                        std::uint32_t divisor = 1, std::uint32_t samples = 1, std::uint32_t alpha = 0) {
    return {(frame.width + divisor - 1) / divisor, (frame.height + divisor - 1) / divisor, format, samples, alpha};
}

}  // namespace engine::render
