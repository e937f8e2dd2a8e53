// SPDX-License-Identifier: MIT
#include "engine/render/frame_graph/transient_texture_pool.hpp"

#include <algorithm>
#include <string>

#include "engine/render/frame_graph/backend_textures.hpp"

namespace engine::render {

TransientTexturePool::~TransientTexturePool() {
    for (const Entry& e : entries_) backend_.destroy(e.texture);
}

TextureAllocator TransientTexturePool::allocator() {
    return {[this](std::string_view name, const FrameGraphTextureDesc& desc) { return allocate(name, desc); },
            [this](ConcreteTexture texture, const FrameGraphTextureDesc&) { release(texture); }};
}

ConcreteTexture TransientTexturePool::allocate(std::string_view name, const FrameGraphTextureDesc& desc) {
    auto free =
        std::find_if(entries_.begin(), entries_.end(), [&](const Entry& e) { return !e.inUse && e.desc == desc; });
    if (free == entries_.end()) {
        // The first user's name labels the texture (debuggers, validation messages).
        const TextureHandle t = backend_.createTexture(backendDescOf(name, desc));
        entries_.push_back({desc, t});
        free = entries_.end() - 1;
    }
    free->inUse = true;
    free->lastUsed = frame_;
    return toConcrete(free->texture);
}

void TransientTexturePool::release(ConcreteTexture texture) {
    const TextureHandle handle = toTextureHandle(texture);
    for (Entry& e : entries_)
        if (e.texture == handle) e.inUse = false;
}

void TransientTexturePool::endFrame() {
    ++frame_;
    std::erase_if(entries_, [&](const Entry& e) {
        if (e.inUse || frame_ - e.lastUsed <= kRetireAfterFrames) return false;
        backend_.destroy(e.texture);
        return true;
    });
}

}  // namespace engine::render
