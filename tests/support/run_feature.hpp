// SPDX-License-Identifier: MIT
#pragma once
// Living-scene features run as the racer runs them (run_graph.hpp): frame.color and
// frame.depth imported, each feature's passes in order, then "present".
#include <string>
#include <vector>

#include "engine/scene/frame_feature.hpp"
#include "run_graph.hpp"

namespace test_support {

// Adds `features`' passes, in order, onto `targets` (frame.color and frame.depth as `one`
// knows them); returns the versions they leave.
inline engine::render::ColorDepth addFeatures(OneFrameGraph& one, const std::vector<engine::scene::Feature*>& features,
                                              const engine::scene::FeatureFrame& frame,
                                              engine::render::ColorDepth targets) {
    for (engine::scene::Feature* f : features) targets = f->addPasses(one.graph(), frame, targets);
    return targets;
}

// One frame of `features` onto frame.color and frame.depth; returns the passes that ran.
inline std::vector<std::string> runFeatures(const std::vector<engine::scene::Feature*>& features,
                                            const engine::scene::FeatureFrame& frame) {
    OneFrameGraph one(frame.backend);
    return one.run(addFeatures(one, features, frame, one.import(frame.color, frame.depth)));
}

}  // namespace test_support
