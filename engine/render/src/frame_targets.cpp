// SPDX-License-Identifier: MIT
#include "engine/render/frame_targets.hpp"

#include <string>
#include <utility>

#include "engine/core/error.hpp"
#include "engine/render/frame_graph.hpp"
#include "engine/render/frame_graph/backend_textures.hpp"

namespace engine::render {

FrameTargets::FrameTargets(Backend& backend, const FrameTargetsDesc& desc) : backend_(backend), desc_(desc) {
    if (desc.samples != 1 && desc.samples != 2 && desc.samples != 4 && desc.samples != 8)
        throw engine::Error("frame targets: " + std::to_string(desc.samples) + " samples (use 1, 2, 4 or 8)");
    auto target = [&](const char* name, Format format, int samples) {
        return backend_.createTexture(renderTargetDesc(name, desc.width, desc.height, format, samples));
    };
    try {
        color_ = target("rt_opaque", desc.colorFormat, 1);
        depth_ = target("rt_depth", Format::D32F, 1);
        if (desc.samples > 1) {
            msaaColor_ = target("rt_opaque_msaa", desc.colorFormat, desc.samples);
            msaaDepth_ = target("rt_depth_msaa", Format::D32F, desc.samples);
        }
    } catch (...) {
        // No destructor runs for a constructor that throws: the targets made so far go here
        // (a refused window size must not leak the ones that fitted).
        release();
        throw;
    }
}

FrameTargets::~FrameTargets() { release(); }

void FrameTargets::release() {
    for (TextureHandle* t : {&color_, &depth_, &msaaColor_, &msaaDepth_})
        if (*t) backend_.destroy(std::exchange(*t, TextureHandle{}));
}

float FrameTargets::farDepth() const { return isCloser(desc_.depthFunc, 0.0f, 1.0f) ? 1.0f : 0.0f; }

PassDesc FrameTargets::passDesc(const glm::vec4& clearColor) const {
    PassDesc pass;
    pass.name = "opaque";
    pass.color[0] = {msaaColor_ ? msaaColor_ : color_, LoadOp::Clear, clearColor};
    pass.depth = {msaaDepth_ ? msaaDepth_ : depth_, LoadOp::Clear, farDepth()};
    return pass;
}

PassDesc FrameTargets::loadPassDesc() const {
    PassDesc pass;
    pass.name = "opaque (load)";
    pass.color[0] = {msaaColor_ ? msaaColor_ : color_, LoadOp::Load};
    pass.depth = {msaaDepth_ ? msaaDepth_ : depth_, LoadOp::Load};
    return pass;
}

void FrameTargets::resolve() {
    if (!msaaColor_) return;
    backend_.resolve({msaaColor_, color_, desc_.depthFunc});
    backend_.resolve({msaaDepth_, depth_, desc_.depthFunc, desc_.depthResolve});
}

FrameTargets::InGraph FrameTargets::importInto(FrameGraph& graph) const {
    auto import = [&](const char* name, TextureHandle t) {
        return graph.importTexture(name, graphDescOf(backend_.describe(t)), toConcrete(t));
    };
    InGraph in;
    in.resolved = {import("rt_opaque", color_), import("rt_depth", depth_)};
    in.drawn = msaaColor_ ? ColorDepth{import("rt_opaque_msaa", msaaColor_), import("rt_depth_msaa", msaaDepth_)}
                          : in.resolved;
    return in;
}

ColorDepth FrameTargets::addResolvePass(FrameGraph& graph, const ColorDepth& drawn, const ColorDepth& resolved) {
    if (!msaaColor_) return drawn;
    struct Data {
        ColorDepth resolved;
    };
    return graph
        .addPass<Data>(
            "resolve",
            [&](FrameGraph::Builder& b, Data& d) {
                b.read(drawn.color);
                b.read(drawn.depth);
                d.resolved = {b.write(resolved.color), b.write(resolved.depth)};
            },
            [this](const FrameGraph::Resources&, const Data&) { resolve(); })
        .resolved;
}

}  // namespace engine::render
