// SPDX-License-Identifier: MIT
#include "engine/scene/frame_feature.hpp"

#include <string>

#include "engine/render/frame_graph.hpp"

namespace engine::scene {

using render::ColorDepth;
using render::FrameGraph;

ColorDepth Feature::addPasses(FrameGraph& graph, const FeatureFrame& frame, const ColorDepth& targets) {
    struct Data {
        ColorDepth out;
    };
    const bool empty = !prepare(frame);
    return graph
        .addPass<Data>(
            std::string(name()),
            [&](FrameGraph::Builder& b, Data& d) {
                d.out.color = b.write(b.read(targets.color));
                d.out.depth = writesDepth() ? b.write(b.read(targets.depth)) : b.read(targets.depth);
                if (empty) b.markEmpty();
            },
            [this, frame](const FrameGraph::Resources&, const Data&) { draw(frame); })
        .out;
}

}  // namespace engine::scene
