// SPDX-License-Identifier: MIT
// FrameGraph::execute(): runs the surviving passes in order, giving transient textures
// real backing from the caller's allocator only while some pass needs them; and the
// Resources accessor passes use to find those real textures.
#include "engine/render/frame_graph.hpp"

#include "engine/core/error.hpp"

#include <algorithm>
#include <string>
#include <vector>

namespace engine::render {

using namespace frame_graph_detail;  // the graph's nodes (frame_graph/graph_nodes.hpp)

void FrameGraph::execute(const TextureAllocator& allocator) {
    // Refused rather than repeated: passes may hold references to data of the frame the
    // graph was built for (frame_graph.hpp).
    if (ran_) throw Error("frame graph: execute() was already called; a graph runs once, build a new one per frame");
    compile();
    executed_.clear();

    // Fail before any pass runs rather than halfway through a frame.
    const bool needsAllocator =
        std::any_of(allocateBefore_.begin(), allocateBefore_.end(), [](const auto& list) { return !list.empty(); });
    if (needsAllocator && (!allocator.allocate || !allocator.release)) {
        const auto first = std::find_if(allocateBefore_.begin(), allocateBefore_.end(),
                                        [](const auto& list) { return !list.empty(); });
        throw Error("frame graph: transient texture '" + resources_[first->front()].name +
                    "' needs allocating, but execute() was given no allocate/release callbacks");
    }

    std::vector<ConcreteTexture> textures(resources_.size(), 0);
    for (std::size_t r = 0; r < resources_.size(); ++r) {
        if (resources_[r].imported) textures[r] = resources_[r].importedTexture;
    }

    ran_ = true;
    std::vector<std::uint32_t> live;  // allocated and not yet released, for cleanup if a pass throws
    try {
        for (std::size_t position = 0; position < executionOrder_.size(); ++position) {
            for (std::uint32_t r : allocateBefore_[position]) {
                textures[r] = allocator.allocate(resources_[r].name, resources_[r].desc);
                live.push_back(r);
            }
            const std::uint32_t pass = executionOrder_[position];
            passes_[pass].executor->execute(FrameGraphResources(*this, pass, textures));
            executed_.push_back(passes_[pass].name);
            for (std::uint32_t r : releaseAfter_[position]) {
                live.erase(std::find(live.begin(), live.end(), r));
                allocator.release(textures[r], resources_[r].desc);
            }
        }
    } catch (...) {
        for (std::uint32_t r : live) allocator.release(textures[r], resources_[r].desc);
        throw;
    }
}

ConcreteTexture FrameGraphResources::get(FrameGraphTexture texture) const {
    const PassNode& pass = graph_.passes_[pass_];
    const VirtualResource& res = graph_.resource(texture, "pass '" + pass.name + "'");
    auto isThisResource = [&](std::uint32_t node) { return graph_.nodes_[node].resource == texture.resource(); };
    // Creating a texture is not using it: only reads and writes give it a lifetime.
    const bool declared = std::any_of(pass.reads.begin(), pass.reads.end(), isThisResource) ||
                          std::any_of(pass.writes.begin(), pass.writes.end(), isThisResource);
    if (!declared) {
        throw Error("frame graph: pass '" + pass.name + "' uses '" + res.name +
                    "' in execute but did not read or write it in setup");
    }
    return textures_[texture.resource()];
}

const FrameGraphTextureDesc& FrameGraphResources::desc(FrameGraphTexture texture) const {
    return graph_.resource(texture, "pass '" + graph_.passes_[pass_].name + "'").desc;
}

std::string_view FrameGraphResources::passName() const { return graph_.passes_[pass_].name; }

}  // namespace engine::render
