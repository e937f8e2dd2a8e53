// SPDX-License-Identifier: MIT
#include "engine/render/frame_graph/side_effect_pass.hpp"

#include <utility>

#include "engine/render/frame_graph.hpp"

namespace engine::render {

void addSideEffectPass(FrameGraph& graph, std::string name, const ColorDepth& frame, std::function<void()> run) {
    struct Data {};
    graph.addPass<Data>(
        std::move(name),
        [&](FrameGraph::Builder& b, Data&) {
            b.read(frame.color);
            b.read(frame.depth);
            b.sideEffect();
        },
        [run = std::move(run)](const FrameGraph::Resources&, const Data&) {
            if (run) run();
        });
}

}  // namespace engine::render
