// SPDX-License-Identifier: MIT
#include "racer_outputs.hpp"

#include <cstdio>
#include <fstream>
#include <vector>

#include "engine/capture/image_write.hpp"
#include "engine/core/output_file.hpp"
#include "engine/core/usage_error.hpp"
#include "layer_pictures.hpp"

namespace racer {

namespace fs = std::filesystem;
namespace cap = engine::capture;

namespace {

// A name without a writer is a usage error (exit 2), not a failed run.
void requireExtension(const fs::path& path, std::initializer_list<std::string_view> extensions) {
    try {
        cap::requireImageExtension(path, extensions);
    } catch (const engine::Error& e) {
        throw engine::UsageError(std::string("--capture: ") + e.what());
    }
}

void writeText(const fs::path& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary);
    out << text;
    out.close();
    if (!out) throw engine::Error("cannot write '" + path.string() + "'");
}

}  // namespace

OutputPlan planOutputs(const Options& o) {
    OutputPlan plan;
    if (!o.capturePath.empty()) {
        plan.capture = o.capturePath;
        if (o.captureLayers) {
            plan.layersExr = fs::path(plan.capture).replace_extension(".exr");
            if (plan.layersExr == plan.capture)
                throw engine::UsageError("--capture-layers writes the layers to '" + plan.layersExr.string() +
                                         "', the --capture file itself: give --capture a .png name");
            requireExtension(plan.capture, {".png"});
        } else {
            requireExtension(plan.capture, {".png", ".exr"});
        }
        engine::requireWritableFile(plan.capture, /*createDirectory=*/true);
        if (!plan.layersExr.empty()) engine::requireWritableFile(plan.layersExr, /*createDirectory=*/true);
    }
    if (!o.layerPictures.empty()) {
        plan.layerPictures = o.layerPictures;
        engine::requireWritableDirectory(plan.layerPictures, /*create=*/true);
    }
    if (!o.dumpGraphPath.empty()) {
        plan.graph = o.dumpGraphPath;
        if (plan.graph.extension() != ".dot")
            throw engine::UsageError("--dump-graph '" + plan.graph.string() +
                                     "': the graph is written as Graphviz "
                                     "dot, give a .dot name");
        engine::requireWritableFile(plan.graph, /*createDirectory=*/true);
    }
    return plan;
}

void writeOutputs(const OutputPlan& plan, const FrameOutputs& frame, const std::string& picturePrefix, float nearPlane,
                  float farPlane) {
    const std::span<const cap::CapturedLayer> layers = frame.layers;
    engine::PendingFiles files;
    std::vector<std::string> report;
    if (!plan.capture.empty()) {
        cap::writeImage(files.add(plan.capture), *frame.color);
        report.push_back("wrote " + plan.capture.string());
    }
    if (!plan.layersExr.empty()) {
        cap::writeLayersExr(files.add(plan.layersExr), layers);
        report.push_back("wrote " + plan.layersExr.string() + " (" + std::to_string(layers.size()) + " layers)");
    }
    if (!plan.layerPictures.empty()) {
        for (const cap::CapturedLayer& layer : layers)
            cap::writePng(files.add(plan.layerPictures / (picturePrefix + layer.name + ".png")),
                          layerPicture(layer, nearPlane, farPlane));
        report.push_back("wrote " + std::to_string(layers.size()) + " layer pictures to " +
                         plan.layerPictures.string());
    }
    if (!plan.graph.empty()) {
        writeText(files.add(plan.graph), frame.graphDot);
        report.push_back("wrote " + plan.graph.string() + " (the last frame's graph)");
    }
    files.commit();
    for (const std::string& line : report) std::printf("racer: %s\n", line.c_str());
}

}  // namespace racer
