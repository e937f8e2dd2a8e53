// SPDX-License-Identifier: MIT
#pragma once
// The bridge between the frame graph's opaque ConcreteTexture and a Backend's
// TextureHandle: the handle's index and generation packed in one integer, and an
// allocator that creates transient render targets on the backend.
#include "engine/render/backend.hpp"
#include "engine/render/frame_graph/texture_allocator.hpp"

namespace engine::render {

inline ConcreteTexture toConcrete(TextureHandle h) { return (ConcreteTexture(h.index) << 32) | h.generation; }
inline TextureHandle toTextureHandle(ConcreteTexture c) {
    return {static_cast<std::uint32_t>(c >> 32), static_cast<std::uint32_t>(c & 0xffffffffu)};
}

inline FrameGraphTextureDesc graphDescOf(const TextureDesc& d) {
    return {static_cast<std::uint32_t>(d.width), static_cast<std::uint32_t>(d.height),
            static_cast<std::uint32_t>(d.format), static_cast<std::uint32_t>(d.samples)};
}

// Transient textures become sampled render targets of the backend, destroyed on release.
inline TextureAllocator backendTextureAllocator(Backend& backend) {
    return {[&backend](std::string_view name, const FrameGraphTextureDesc& d) {
                return toConcrete(backend.createTexture(
                    renderTargetDesc(std::string(name), static_cast<int>(d.width), static_cast<int>(d.height),
                                     static_cast<Format>(d.format), static_cast<int>(d.samples))));
            },
            [&backend](ConcreteTexture c, const FrameGraphTextureDesc&) { backend.destroy(toTextureHandle(c)); }};
}

}  // namespace engine::render
