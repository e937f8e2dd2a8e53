// SPDX-License-Identifier: MIT
#pragma once
// The frame graph's transient textures kept across frames: allocator() hands the graph a
// texture of the same descriptor that an earlier frame released, creating one only when
// none is free, so a steady-state frame creates no texture. Within a frame, a texture
// released after its last user can serve a later transient of the same descriptor (the
// graph's lifetimes make that safe). Textures unused for kRetireAfterFrames frames are
// destroyed at endFrame().
#include <cstddef>
#include <cstdint>
#include <vector>

#include "engine/render/backend.hpp"
#include "engine/render/frame_graph/texture_allocator.hpp"

namespace engine::render {

class TransientTexturePool {
public:
    static constexpr std::uint64_t kRetireAfterFrames = 120;

    explicit TransientTexturePool(Backend& backend) : backend_(backend) {}
    ~TransientTexturePool();
    TransientTexturePool(const TransientTexturePool&) = delete;
    TransientTexturePool& operator=(const TransientTexturePool&) = delete;

    // For FrameGraph::execute(); valid while the pool lives.
    TextureAllocator allocator();
    void endFrame();

    std::size_t texturesHeld() const { return entries_.size(); }

private:
    struct Entry {
        FrameGraphTextureDesc desc;
        TextureHandle texture;
        std::uint64_t lastUsed = 0;
        bool inUse = false;
    };
    ConcreteTexture allocate(std::string_view name, const FrameGraphTextureDesc& desc);
    void release(ConcreteTexture texture);

    Backend& backend_;
    std::vector<Entry> entries_;
    std::uint64_t frame_ = 0;
};

}  // namespace engine::render
