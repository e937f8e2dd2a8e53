// SPDX-License-Identifier: MIT
#pragma once
// Most techniques add one frame-graph pass, named after the technique, that does the whole
// frame's work: it reads and writes the frame's targets (the MSAA ones too when
// multisampled: alpha testing and alpha-to-coverage draw into them before they resolve) and
// creates the targets the technique draws through as the graph's transients, so the graph,
// not the technique, owns them.
#include <span>
#include <string>
#include <vector>

#include "transparency/technique.hpp"

namespace transparency::detail {

// A target such a technique draws a frame through and needs no longer: a transient its pass creates.
struct TransientTarget {
    std::string layer;                 // its name among the captured layers (racer --capture-layers)
    engine::render::TextureDesc desc;  // a render target of the frame's size (renderTargetDesc)
};

class SinglePassTechnique : public Technique {
public:
    using Technique::Technique;

    engine::render::ColorDepth addPasses(engine::render::FrameGraph& graph, engine::render::FrameTargets& opaque,
                                         const engine::render::ColorDepth& drawn,
                                         const engine::render::ColorDepth& resolved, const FoliageFrame& frame) final;

    // The targets a frame of width x height with colour in `colorFormat` needs, in the order
    // drawFrame() takes them; none when there is nothing to draw (no foliage in view) or the
    // technique needs none.
    virtual std::vector<TransientTarget> transientTargets(int /*width*/, int /*height*/,
                                                          engine::render::Format /*colorFormat*/,
                                                          const FoliageFrame& /*frame*/) const {
        return {};
    }
    // The pass's work, called after the opaque pass drew into `opaque` and BEFORE
    // opaque.resolve(): draws the foliage through `targets` (backend textures as
    // transientTargets() described them), resolves, and leaves the final colour in
    // opaque.color() and, in opaque.depth(), the depth later passes test against. Public so
    // that the temporal pass can run the technique it follows inside its own pass.
    virtual void drawFrame(engine::render::FrameTargets& opaque, const FoliageFrame& frame,
                           std::span<const engine::render::TextureHandle> targets) = 0;
};

}  // namespace transparency::detail
