// SPDX-License-Identifier: MIT
#pragma once
// The bridge between the frame graph's opaque ConcreteTexture and a Backend's
// TextureHandle: the handle's index and generation packed in one integer, an allocator
// that creates transient render targets on the backend, and what a transient weighs.
#include "engine/render/backend.hpp"
#include "engine/render/format.hpp"
#include "engine/render/frame_graph/texture_allocator.hpp"

namespace engine::render {

inline ConcreteTexture toConcrete(TextureHandle h) { return (ConcreteTexture(h.index) << 32) | h.generation; }
inline TextureHandle toTextureHandle(ConcreteTexture c) {
    return {static_cast<std::uint32_t>(c >> 32), static_cast<std::uint32_t>(c & 0xffffffffu)};
}

inline FrameGraphTextureDesc graphDescOf(const TextureDesc& d) {
    return {static_cast<std::uint32_t>(d.width), static_cast<std::uint32_t>(d.height),
            static_cast<std::uint32_t>(d.format), static_cast<std::uint32_t>(d.samples),
            static_cast<std::uint32_t>(d.alpha)};
}

// The render target a transient becomes: sampled by later passes, as renderTargetDesc().
inline TextureDesc backendDescOf(std::string_view name, const FrameGraphTextureDesc& d) {
    TextureDesc t = renderTargetDesc(std::string(name), static_cast<int>(d.width), static_cast<int>(d.height),
                                     static_cast<Format>(d.format), static_cast<int>(d.samples));
    t.alpha = static_cast<AlphaMode>(d.alpha);
    return t;
}

// The bytes a transient holds: every sample of every pixel (FrameGraph::peakTransientBytes).
inline std::uint64_t backendTextureBytes(const FrameGraphTextureDesc& d) {
    return std::uint64_t(d.width) * d.height * d.samples * formatInfo(static_cast<Format>(d.format)).bytesPerPixel;
}

// Transient textures become sampled render targets of the backend, destroyed on release.
inline TextureAllocator backendTextureAllocator(Backend& backend) {
    return {[&backend](std::string_view name, const FrameGraphTextureDesc& d) {
                return toConcrete(backend.createTexture(backendDescOf(name, d)));
            },
            [&backend](ConcreteTexture c, const FrameGraphTextureDesc&) { backend.destroy(toTextureHandle(c)); }};
}

}  // namespace engine::render
