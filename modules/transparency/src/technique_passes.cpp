// SPDX-License-Identifier: MIT
// Technique::addPasses's default: the technique's whole work as one frame-graph pass.
#include "engine/render/frame_graph.hpp"
#include "transparency/technique.hpp"

namespace transparency {

using namespace engine::render;

ColorDepth Technique::addPasses(FrameGraph& graph, FrameTargets& opaque, const ColorDepth& drawn,
                                const ColorDepth& resolved, const FoliageFrame& frame) {
    struct Data {
        ColorDepth resolved;
    };
    const bool multisampled = drawn != resolved;
    return graph
        .addPass<Data>(
            techniqueName(kind()),
            [&](FrameGraph::Builder& b, Data& d) {
                // Alpha testing and alpha-to-coverage draw into the MSAA targets before they
                // resolve; the others resolve first and draw onto the resolved frame.
                if (multisampled) b.write(b.read(drawn.color)), b.write(b.read(drawn.depth));
                d.resolved = {b.write(multisampled ? resolved.color : b.read(resolved.color)),
                              b.write(multisampled ? resolved.depth : b.read(resolved.depth))};
            },
            [this, &opaque, frame](const FrameGraph::Resources&, const Data&) { render(opaque, frame); })
        .resolved;
}

}  // namespace transparency
