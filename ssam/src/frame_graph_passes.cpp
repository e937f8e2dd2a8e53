// SPDX-License-Identifier: MIT
#include "ssam/frame_graph_passes.hpp"

#include <memory>

#include "engine/render/frame_graph/backend_textures.hpp"

namespace ssam {

using namespace engine::render;

ColorDepth addSsamPasses(FrameGraph& graph, ScreenSpaceAlphaMask& ssam, const FoliageView& view,
                         const ColorDepth& frame) {
    const FrameGraphTexture color = frame.color, depth = frame.depth;
    const FrameGraphTextureDesc colorDesc = graph.desc(color);
    auto plan = std::make_shared<const FramePlan>(
        ssam.plan(int(colorDesc.width), int(colorDesc.height), static_cast<Format>(colorDesc.format), view));
    const bool empty = plan->empty();

    // SSAM owns its intermediates across frames, so the graph imports them; with nothing in
    // view they don't exist and the passes that would write them are empty.
    Backend& backend = ssam.backend();
    const Intermediates targets = ssam.intermediates();
    auto import = [&](const char* name, TextureHandle h) {
        return h ? graph.importTexture(name, graphDescOf(backend.describe(h)), toConcrete(h)) : FrameGraphTexture{};
    };
    const FrameGraphTexture mask = import("rt_mask", targets.mask);
    const FrameGraphTexture maskAdd = import("rt_mask_add", targets.maskAdd);
    const FrameGraphTexture foliage = import("rt_foliage", targets.foliage);

    struct MaskData {
        FrameGraphTexture depth, mask, maskAdd;
    };
    const MaskData& maskPass = graph.addPass<MaskData>(
        "ssam mask",
        [&](FrameGraph::Builder& b, MaskData& d) {
            d.depth = b.read(depth);
            if (empty) {
                d.mask = b.write(b.create("rt_mask", colorDesc));
                b.markEmpty();
                return;
            }
            d.mask = b.write(mask);
            if (maskAdd.isValid()) d.maskAdd = b.write(maskAdd);
        },
        [&ssam, &view, plan](const FrameGraph::Resources& r, const MaskData& d) {
            ssam.maskPass(*plan, view, toTextureHandle(r.get(d.depth)));
        });

    struct ColorData {
        FrameGraphTexture depth, foliage;
    };
    const ColorData& colorPass = graph.addPass<ColorData>(
        "ssam colour",
        [&](FrameGraph::Builder& b, ColorData& d) {
            d.depth = b.write(b.read(maskPass.depth));  // foliage depth joins the opaque depth
            if (empty) {
                d.foliage = b.write(b.create("rt_foliage", colorDesc));
                b.markEmpty();
                return;
            }
            d.foliage = b.write(foliage);
        },
        [&ssam, &view, plan](const FrameGraph::Resources& r, const ColorData& d) {
            ssam.colorPass(*plan, view, toTextureHandle(r.get(d.depth)));
        });

    struct CompositeData {
        FrameGraphTexture color;
    };
    const CompositeData& compositePass = graph.addPass<CompositeData>(
        "ssam composite",
        [&](FrameGraph::Builder& b, CompositeData& d) {
            b.read(maskPass.mask);
            if (maskPass.maskAdd.isValid()) b.read(maskPass.maskAdd);
            b.read(colorPass.foliage);
            d.color = b.write(b.read(color));  // blended in place onto the opaque colour
            if (empty) b.markEmpty();
        },
        [&ssam, plan](const FrameGraph::Resources& r, const CompositeData& d) {
            ssam.compositePass(*plan, toTextureHandle(r.get(d.color)));
        });

    return {compositePass.color, colorPass.depth};
}

}  // namespace ssam
