// SPDX-License-Identifier: MIT
// The technique's whole work as one frame-graph pass (single_pass_technique.hpp).
#include "engine/render/frame_graph.hpp"
#include "engine/render/frame_graph/backend_textures.hpp"
#include "single_pass_technique.hpp"

namespace transparency::detail {

using namespace engine::render;

ColorDepth SinglePassTechnique::addPasses(FrameGraph& graph, FrameTargets& opaque, const ColorDepth& drawn,
                                          const ColorDepth& resolved, const FoliageFrame& frame) {
    struct Data {
        ColorDepth resolved;
        std::vector<FrameGraphTexture> targets;  // transientTargets(), in order
    };
    const bool multisampled = drawn != resolved;
    const FrameGraphTextureDesc size = graph.desc(resolved.color);
    const std::vector<TransientTarget> transients =
        transientTargets(int(size.width), int(size.height), Format(size.format), frame);
    const Data& data = graph.addPass<Data>(
        techniqueName(kind()),
        [&](FrameGraph::Builder& b, Data& d) {
            // Alpha testing and alpha-to-coverage draw into the MSAA targets before they
            // resolve; the others resolve first and draw onto the resolved frame.
            if (multisampled) b.write(b.read(drawn.color)), b.write(b.read(drawn.depth));
            d.resolved = {b.write(multisampled ? resolved.color : b.read(resolved.color)),
                          b.write(multisampled ? resolved.depth : b.read(resolved.depth))};
            for (const TransientTarget& t : transients)
                d.targets.push_back(b.write(b.create(t.desc.name, graphDescOf(t.desc))));
        },
        [this, &opaque, frame](const FrameGraph::Resources& r, const Data& d) {
            std::vector<TextureHandle> targets;
            for (FrameGraphTexture t : d.targets) targets.push_back(toTextureHandle(r.get(t)));
            drawFrame(opaque, frame, targets);
        });
    graphTargets_.clear();
    for (std::size_t i = 0; i < transients.size(); ++i) graphTargets_.push_back({transients[i].layer, data.targets[i]});
    return data.resolved;
}

}  // namespace transparency::detail
