// SPDX-License-Identifier: MIT
#pragma once
// A Backend that forwards every call to another and counts the bytes of the textures and
// buffers created through it that are still alive: `ssam-bench`'s peak_mem_mb column.
// Handed to a technique (and its FrameTargets), it measures exactly what that technique
// allocates — targets at their sample count, mip chains, buffers — the same numbers on
// every run and backend, unlike a process RSS. Resources created elsewhere (the scene's
// meshes, made on the wrapped backend) pass through uncounted. Capabilities (the soft
// backend's fragment capture, which the exact reference needs) are forwarded.
#include <cstdint>
#include <memory>
#include <unordered_map>

#include "engine/render/backend.hpp"

namespace bench {

// Bytes of a texture as described: every mip level, every sample.
std::uint64_t textureBytes(const engine::render::TextureDesc& desc);

class ResourceCount {
public:
    std::uint64_t liveBytes() const { return live_; }
    std::uint64_t peakBytes() const { return peak_; }

    void created(std::uint64_t key, std::uint64_t bytes, bool texture);
    void destroyed(std::uint64_t key, bool texture);

private:
    std::unordered_map<std::uint64_t, std::uint64_t> textures_, buffers_;  // handle -> bytes
    std::uint64_t live_ = 0, peak_ = 0;
};

// `inner` and `count` must outlive the returned backend.
std::unique_ptr<engine::render::Backend> makeCountingBackend(engine::render::Backend& inner, ResourceCount& count);

}  // namespace bench
