// SPDX-License-Identifier: MIT
#pragma once
// One foliage frame of a transparency technique, run as the racer runs it (run_graph.hpp):
// `opaque`'s targets imported after the caller drew the opaque pass into them, the
// technique's passes, then "present". The technique's transients can be read back.
#include <string>
#include <vector>

#include "engine/render/frame_targets.hpp"
#include "run_graph.hpp"
#include "transparency/technique.hpp"

namespace test_support {

struct TechniqueRun {
    std::vector<std::string> passes;  // the passes that ran, "present" last
    // The transients the technique wrote (Technique::graphIntermediates), by layer name.
    std::vector<std::pair<std::string, engine::render::Readback>> layers;
};

inline TechniqueRun runTechnique(engine::render::Backend& backend, transparency::Technique& technique,
                                 engine::render::FrameTargets& opaque, const transparency::FoliageFrame& frame,
                                 bool readLayers = false) {
    OneFrameGraph one(backend);
    const engine::render::FrameTargets::InGraph in = opaque.importInto(one.graph());
    const engine::render::ColorDepth out = technique.addPasses(one.graph(), opaque, in.drawn, in.resolved, frame);
    std::vector<engine::render::FrameGraphTexture> layers;
    for (const transparency::GraphTarget& t : technique.graphIntermediates()) layers.push_back(t.texture);
    const std::size_t first = readLayers ? one.readBack(layers) : 0;
    TechniqueRun run{one.run(out), {}};
    if (readLayers)
        for (std::size_t i = 0; i < layers.size(); ++i)
            run.layers.emplace_back(technique.graphIntermediates()[i].layer, one.readBacks()[first + i]);
    return run;
}

}  // namespace test_support
