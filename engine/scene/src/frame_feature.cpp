// SPDX-License-Identifier: MIT
#include "engine/scene/frame_feature.hpp"

#include <string>

#include "engine/render/frame_graph.hpp"

namespace engine::scene {

using render::ColorDepth;
using render::FrameGraph;

ColorDepth Feature::addDrawPass(FrameGraph& graph, const FeatureFrame& frame, const ColorDepth& targets, bool empty,
                                DepthUse depth, std::function<void(const FeatureFrame&)> draw) const {
    struct Data {
        ColorDepth out;
    };
    return graph
        .addPass<Data>(
            std::string(name()),
            [&](FrameGraph::Builder& b, Data& d) {
                d.out.color = b.write(b.read(targets.color));
                d.out.depth = depth == DepthUse::TestAndWrite ? b.write(b.read(targets.depth)) : b.read(targets.depth);
                if (empty) b.markEmpty();
            },
            [draw = std::move(draw), frame](const FrameGraph::Resources&, const Data&) { draw(frame); })
        .out;
}

}  // namespace engine::scene
