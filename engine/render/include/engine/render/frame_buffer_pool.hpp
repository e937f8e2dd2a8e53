// SPDX-License-Identifier: MIT
#pragma once
// Buffers whose contents change every frame (instance transforms, particle quads) without
// creating a buffer every frame: upload() hands out a buffer that held data of the same
// name and kind in an earlier frame and is large enough, writing the new data at its
// start; only when none fits is one created, with room to grow (a power of two). So a
// steady-state frame creates no buffer at all (FramePooling tests count creations).
//
// A buffer handed out stays valid until the next beginFrame(). Draws read only the range
// they name, so the bytes past the data (left from an earlier frame) are never used; for an
// index buffer they may hold larger indices than this frame's, which validation only costs
// a scan of the draw's own range. Buffers unused for kRetireAfterFrames frames are
// destroyed, so a view that once needed many does not keep them forever.
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "engine/render/backend.hpp"

namespace engine::render {

class FrameBufferPool {
public:
    static constexpr std::uint64_t kRetireAfterFrames = 120;
    static constexpr std::uint64_t kMinimumElements = 1;  // a one-instance batch costs one instance

    explicit FrameBufferPool(Backend& backend) : backend_(backend) {}
    ~FrameBufferPool();
    FrameBufferPool(const FrameBufferPool&) = delete;
    FrameBufferPool& operator=(const FrameBufferPool&) = delete;

    // Everything handed out so far may be reused; retires buffers left unused too long.
    void beginFrame();
    // A buffer of `kind` holding `data` from offset 0, valid until the next beginFrame().
    // Throws engine::Error (from the backend) when it cannot be created; the pool is unchanged.
    BufferHandle upload(const std::string& name, BufferKind kind, std::span<const std::byte> data);

    std::size_t buffersHeld() const { return entries_.size(); }

private:
    struct Entry {
        std::string name;
        BufferKind kind;
        BufferHandle buffer;
        std::uint64_t capacity = 0;
        std::uint64_t lastUsed = 0;  // frame number
        bool inUse = false;
    };

    Backend& backend_;
    std::vector<Entry> entries_;
    std::uint64_t frame_ = 0;
};

}  // namespace engine::render
