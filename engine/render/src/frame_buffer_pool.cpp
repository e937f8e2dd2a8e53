// SPDX-License-Identifier: MIT
#include "engine/render/frame_buffer_pool.hpp"

#include <algorithm>
#include <bit>

namespace engine::render {

FrameBufferPool::~FrameBufferPool() {
    for (const Entry& e : entries_) backend_.destroy(e.buffer);
}

void FrameBufferPool::beginFrame() {
    ++frame_;
    std::erase_if(entries_, [&](Entry& e) {
        e.inUse = false;
        if (frame_ - e.lastUsed <= kRetireAfterFrames) return false;
        backend_.destroy(e.buffer);
        return true;
    });
}

BufferHandle FrameBufferPool::upload(const std::string& name, BufferKind kind, std::span<const std::byte> data) {
    // Best fit among the free buffers of this name and kind: the smallest that holds the data.
    Entry* best = nullptr;
    for (Entry& e : entries_)
        if (!e.inUse && e.kind == kind && e.capacity >= data.size() && e.name == name &&
            (!best || e.capacity < best->capacity))
            best = &e;
    if (!best) {
        // Room for a power of two of elements, so a growing need creates few buffers.
        const std::uint64_t element = elementSize(kind);
        const std::uint64_t elements = std::max<std::uint64_t>((data.size() + element - 1) / element, 1);
        const std::uint64_t capacity = element * std::bit_ceil(std::max(elements, kMinimumElements));
        const BufferHandle buffer = backend_.createBuffer({name, kind, capacity}, {});
        entries_.push_back({name, kind, buffer, capacity, frame_, false});
        best = &entries_.back();
    }
    if (!data.empty()) backend_.updateBuffer(best->buffer, 0, data);
    best->inUse = true;
    best->lastUsed = frame_;
    return best->buffer;
}

}  // namespace engine::render
