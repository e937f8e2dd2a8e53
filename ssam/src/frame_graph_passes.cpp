// SPDX-License-Identifier: MIT
#include "ssam/frame_graph_passes.hpp"

#include <memory>

#include "engine/render/frame_graph/backend_textures.hpp"

namespace ssam {

using namespace engine::render;

SsamPasses addSsamPasses(FrameGraph& graph, ScreenSpaceAlphaMask& ssam, const FoliageView& view,
                         const ColorDepth& frame) {
    const FrameGraphTexture color = frame.color, depth = frame.depth;
    const FrameGraphTextureDesc colorDesc = graph.desc(color);
    const int width = int(colorDesc.width), height = int(colorDesc.height);
    auto plan = std::make_shared<const FramePlan>(ssam.cull(width, height, view));
    const bool empty = plan->empty();

    // The intermediates are transients of the frame's size (rt_foliage in its colour format).
    const IntermediateDescs descs = ssam.intermediateDescs(width, height, static_cast<Format>(colorDesc.format));
    auto targetsOf = [](const FrameGraph::Resources& r, FrameGraphTexture mask, FrameGraphTexture maskAdd,
                        FrameGraphTexture foliage, FrameGraphTexture depthCopy = {}) {
        Intermediates t;
        if (mask.isValid()) t.mask = toTextureHandle(r.get(mask));
        if (maskAdd.isValid()) t.maskAdd = toTextureHandle(r.get(maskAdd));
        if (foliage.isValid()) t.foliage = toTextureHandle(r.get(foliage));
        if (depthCopy.isValid()) t.depthCopy = toTextureHandle(r.get(depthCopy));
        return t;
    };

    struct MaskData {
        FrameGraphTexture depth, mask, maskAdd;
    };
    const MaskData& maskPass = graph.addPass<MaskData>(
        "ssam mask",
        [&](FrameGraph::Builder& b, MaskData& d) {
            d.depth = b.read(depth);
            d.mask = b.write(b.create(descs.mask.name, graphDescOf(descs.mask)));
            if (descs.maskAdd) d.maskAdd = b.write(b.create(descs.maskAdd->name, graphDescOf(*descs.maskAdd)));
            if (empty) b.markEmpty();
        },
        [&ssam, &view, plan, targetsOf](const FrameGraph::Resources& r, const MaskData& d) {
            ssam.maskPass(*plan, view, toTextureHandle(r.get(d.depth)), targetsOf(r, d.mask, d.maskAdd, {}));
        });

    struct ColorData {
        FrameGraphTexture depth, foliage, depthCopy;
    };
    const ColorData& colorPass = graph.addPass<ColorData>(
        "ssam colour",
        [&](FrameGraph::Builder& b, ColorData& d) {
            if (descs.depthCopy) {  // depthMaskThreshold > 0: drawn into a copy of the opaque depth
                d.depth = b.read(maskPass.depth);
                d.depthCopy = b.write(b.create(descs.depthCopy->name, graphDescOf(*descs.depthCopy)));
            } else {
                d.depth = b.write(b.read(maskPass.depth));  // foliage depth joins the opaque depth
            }
            d.foliage = b.write(b.create(descs.foliage.name, graphDescOf(descs.foliage)));
            if (empty) b.markEmpty();
        },
        [&ssam, &view, plan, targetsOf](const FrameGraph::Resources& r, const ColorData& d) {
            ssam.colorPass(*plan, view, toTextureHandle(r.get(d.depth)), targetsOf(r, {}, {}, d.foliage, d.depthCopy));
        });

    // The composite and the depth restore read the mask pass's targets and one earlier output
    // (`after`), and write `target` in place; InPlaceData keeps the written version.
    struct InPlaceData {
        FrameGraphTexture written;
    };
    auto afterMasksInPlace = [&maskPass, empty](FrameGraph::Builder& b, FrameGraphTexture after,
                                                FrameGraphTexture target) {
        b.read(maskPass.mask);
        if (maskPass.maskAdd.isValid()) b.read(maskPass.maskAdd);
        b.read(after);
        const FrameGraphTexture written = b.write(b.read(target));
        if (empty) b.markEmpty();
        return written;
    };

    const InPlaceData& compositePass = graph.addPass<InPlaceData>(
        "ssam composite",
        [&](FrameGraph::Builder& b, InPlaceData& d) {
            d.written = afterMasksInPlace(b, colorPass.foliage, color);  // blended in place onto the opaque colour
        },
        [&ssam, plan, targetsOf, &maskPass, &colorPass](const FrameGraph::Resources& r, const InPlaceData& d) {
            ssam.compositePass(*plan, toTextureHandle(r.get(d.written)),
                               targetsOf(r, maskPass.mask, maskPass.maskAdd, colorPass.foliage));
        });

    FrameGraphTexture depthOut = colorPass.depth;
    if (descs.depthCopy) {
        // depthMaskThreshold > 0: the foliage depth where the composited mask reaches it.
        const InPlaceData& depthPass = graph.addPass<InPlaceData>(
            "ssam depth restore",
            [&](FrameGraph::Builder& b, InPlaceData& d) {
                // after the composite, as the other hosts' restore
                d.written = afterMasksInPlace(b, compositePass.written, colorPass.depth);
            },
            [&ssam, &view, plan, targetsOf, &maskPass](const FrameGraph::Resources& r, const InPlaceData& d) {
                ssam.foliageDepthPass(*plan, view, toTextureHandle(r.get(d.written)),
                                      targetsOf(r, maskPass.mask, maskPass.maskAdd, {}));
            });
        depthOut = depthPass.written;
    }

    SsamPasses out{{compositePass.written, depthOut}, {}, {}, {}};
    if (!empty) out.mask = maskPass.mask, out.maskAdd = maskPass.maskAdd, out.foliage = colorPass.foliage;
    return out;
}

}  // namespace ssam
