// SPDX-License-Identifier: MIT
#pragma once
// What a pass's execute lambda uses to turn its virtual handles into the real textures
// the allocator (or importTexture()) supplied.
#include "engine/render/frame_graph/texture_allocator.hpp"
#include "engine/render/frame_graph/texture_desc.hpp"
#include "engine/render/frame_graph/texture_handle.hpp"

#include <cstdint>
#include <span>
#include <string_view>

namespace engine::render {

class FrameGraph;

class FrameGraphResources {
public:
    FrameGraphResources(const FrameGraphResources&) = delete;
    FrameGraphResources& operator=(const FrameGraphResources&) = delete;

    // The real texture behind `texture`, any version. Only textures this pass read or wrote
    // in setup are available: anything else would dodge the graph's lifetimes.
    ConcreteTexture get(FrameGraphTexture texture) const;
    const FrameGraphTextureDesc& desc(FrameGraphTexture texture) const;
    std::string_view passName() const;

private:
    friend class FrameGraph;
    FrameGraphResources(const FrameGraph& graph, std::uint32_t pass, std::span<const ConcreteTexture> textures)
        : graph_(graph), pass_(pass), textures_(textures) {}

    const FrameGraph& graph_;
    std::uint32_t pass_;
    std::span<const ConcreteTexture> textures_;  // indexed by resource
};

}  // namespace engine::render
