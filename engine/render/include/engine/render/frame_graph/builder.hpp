// SPDX-License-Identifier: MIT
#pragma once
// What a pass's setup lambda uses to declare its resources. Declarations are checked as
// they are made, so a mistake throws engine::Error from inside the setup that made it,
// naming the pass and the texture.
#include "engine/render/frame_graph/texture_desc.hpp"
#include "engine/render/frame_graph/texture_handle.hpp"

#include <cstdint>
#include <string>

namespace engine::render {

class FrameGraph;

class FrameGraphBuilder {
public:
    FrameGraphBuilder(const FrameGraphBuilder&) = delete;
    FrameGraphBuilder& operator=(const FrameGraphBuilder&) = delete;

    // A new transient texture, owned by the graph. It has no contents (version 0) until a
    // pass writes it; reading it before then is an error.
    FrameGraphTexture create(std::string name, const FrameGraphTextureDesc& desc);

    // This pass reads the texture's contents as of `texture`, which must be the latest
    // version (an older one would be overwritten by the time this pass runs). Returns it.
    FrameGraphTexture read(FrameGraphTexture texture);

    // This pass writes the texture; returns the new version later passes must use. Writing
    // twice in one pass returns the same version.
    FrameGraphTexture write(FrameGraphTexture texture);

    // Never cull this pass (present, capture, readback): its effect is outside the graph.
    void sideEffect();

    // This pass has nothing to do this frame. It will not execute, its reads do not keep
    // producers alive, and its writes leave the texture as it was (see FrameGraph).
    void markEmpty();

    const FrameGraphTextureDesc& desc(FrameGraphTexture texture) const;

private:
    friend class FrameGraph;
    FrameGraphBuilder(FrameGraph& graph, std::uint32_t pass) : graph_(graph), pass_(pass) {}

    FrameGraph& graph_;
    std::uint32_t pass_;
};

}  // namespace engine::render
