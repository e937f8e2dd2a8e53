// SPDX-License-Identifier: MIT
#pragma once
// How the frame graph turns virtual textures into real ones without knowing the backend:
// the caller hands execute() two callbacks. A ConcreteTexture is whatever the backend
// uses to name a texture (an index, a GL name, a pointer cast to an integer).
#include "engine/render/frame_graph/texture_desc.hpp"

#include <cstdint>
#include <functional>
#include <string_view>

namespace engine::render {

using ConcreteTexture = std::uint64_t;

struct TextureAllocator {
    // Called just before the first pass that uses a transient texture; the name is for
    // debugging labels only.
    std::function<ConcreteTexture(std::string_view name, const FrameGraphTextureDesc& desc)> allocate;
    // Called just after the last pass that uses it; the descriptor lets a pool re-bucket it.
    std::function<void(ConcreteTexture texture, const FrameGraphTextureDesc& desc)> release;
};

}  // namespace engine::render
