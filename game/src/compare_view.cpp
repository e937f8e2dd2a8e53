// SPDX-License-Identifier: MIT
#include "compare_view.hpp"

#include "compare_layout.hpp"
#include "engine/render/frame_graph/backend_textures.hpp"
#include "frame_renderer.hpp"

namespace racer {

using namespace engine::render;

CompareView::CompareView(Backend& backend, const engine::scene::MeshLibrary& library, const RendererOptions& options)
    : backend_(backend), right_(std::make_unique<FrameRenderer>(backend, library, options)) {}

CompareView::~CompareView() = default;

FrameGraphTexture CompareView::addPasses(FrameGraph& graph, FrameGraphTexture color, TextureHandle target, int width,
                                         int height, const std::string& leftName, hud::Overlay& overlay) {
    const TextureDesc copyDesc = renderTargetDesc("compare left", width, height, backend_.describe(target).format);
    if (!leftCopy_.get() || backend_.describe(leftCopy_).width != width ||
        backend_.describe(leftCopy_).height != height) {
        Owned<TextureHandle> next(backend_, backend_.createTexture(copyDesc));
        leftCopy_ = std::move(next);
    }
    const FrameGraphTexture leftInGraph =
        graph.importTexture("compare left", graphDescOf(backend_.describe(leftCopy_)), toConcrete(leftCopy_));

    // A's finished frame, copied aside: the insets read it while "compare" draws over A's.
    hud::OverlayContent keep;
    keep.images.push_back({target, color, {0, 0, width, height}, {0, 0}, 1});
    const FrameGraphTexture kept =
        overlay.addPass(graph, "compare: keep left", leftInGraph, leftCopy_, width, height, std::move(keep));

    struct Data {
        FrameGraphTexture out;
    };
    const std::string rightName = transparency::techniqueName(right_->technique());
    return graph
        .addPass<Data>(
            "compare",
            [&](FrameGraph::Builder& b, Data& d) {
                b.read(kept);
                d.out = b.write(b.read(color));
            },
            [this, target, width, height, leftName, rightName, &overlay](const FrameGraph::Resources&, const Data&) {
                const CompareLayout layout = compareLayout(width, height, leftName, rightName);
                // Where the two differ most, from both finished frames.
                const std::vector<float> difference =
                    frameDifference(backend_.readback(leftCopy_), backend_.readback(right_->color()));
                crop_ = mostDifferentCrop(difference, width, height, layout.crop, layout.searchArea);
                marks_ = compareMarks(layout, crop_);
                overlay.draw(target, width, height, compareOverlay(layout, crop_, leftCopy_, right_->color()),
                             "compare");
            })
        .out;
}

}  // namespace racer
