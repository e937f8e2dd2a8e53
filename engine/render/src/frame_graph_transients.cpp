// SPDX-License-Identifier: MIT
// What the compiled frame asks of its transient textures: each one's lifetime, named by
// its first and last pass, and the most bytes they hold at once (racer --dump-graph and
// the HUD report both).
#include "engine/render/frame_graph.hpp"

#include <algorithm>

namespace engine::render {

using frame_graph_detail::VirtualResource;

std::vector<TransientInfo> FrameGraph::transients() const {
    requireCompiled("the transients");
    std::vector<TransientInfo> out;
    for (const std::vector<std::uint32_t>& allocated : allocateBefore_) {
        for (std::uint32_t r : allocated) {
            const VirtualResource& res = resources_[r];
            out.push_back({res.name, res.desc, passes_[executionOrder_[res.lifetime->first]].name,
                           passes_[executionOrder_[res.lifetime->last]].name});
        }
    }
    return out;
}

std::uint64_t FrameGraph::peakTransientBytes(const TextureBytes& bytesOf) const {
    requireCompiled("the peak transient bytes");
    // A transient is alive from just before its first pass to just after its last, so
    // while pass p runs exactly those with first <= p <= last are held.
    std::uint64_t peak = 0;
    for (std::size_t position = 0; position < executionOrder_.size(); ++position) {
        std::uint64_t alive = 0;
        for (const VirtualResource& res : resources_) {
            if (res.imported || !res.lifetime) continue;
            if (res.lifetime->first <= position && position <= res.lifetime->last) alive += bytesOf(res.desc);
        }
        peak = std::max(peak, alive);
    }
    return peak;
}

}  // namespace engine::render
