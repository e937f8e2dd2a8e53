// SPDX-License-Identifier: MIT
#pragma once
// What racer writes -- the --capture image; with --capture-layers, the EXR of every layer
// beside it; with --layer-pictures, a PNG per layer; with --dump-graph, the last frame's
// frame graph as Graphviz dot -- checked before the first frame, so a
// bad path fails at once even on a long run, and written together at the end: each file
// whole, and all of them or none (engine/core/output_file.hpp).
#include <filesystem>
#include <span>
#include <string>

#include "engine/capture/target_capture.hpp"
#include "racer_options.hpp"

namespace racer {

struct OutputPlan {
    std::filesystem::path capture;        // empty: no capture
    std::filesystem::path layersExr;      // empty unless --capture-layers
    std::filesystem::path layerPictures;  // a directory; empty unless --layer-pictures
    std::filesystem::path graph;          // .dot; empty unless --dump-graph

    bool empty() const { return capture.empty() && graph.empty(); }
};

// Before any work. Throws engine::UsageError for a name no writer can produce (--capture
// ends in .png or .exr; with --capture-layers in .png, since the layers take the .exr name)
// and engine::Error for a place where no file can be created, proven by creating one there.
// Creates missing directories, as racer always has.
OutputPlan planOutputs(const Options& o);

// The last frame's colour, layers and graph, written as planned. Layer pictures are named
// <picturePrefix><layer>.png; nearPlane/farPlane scale the depth picture.
struct FrameOutputs {
    const engine::capture::Image* color = nullptr;  // needed when plan.capture is set
    std::span<const engine::capture::CapturedLayer> layers;
    std::string graphDot;  // needed when plan.graph is set
};
void writeOutputs(const OutputPlan& plan, const FrameOutputs& frame, const std::string& picturePrefix, float nearPlane,
                  float farPlane);

}  // namespace racer
