// SPDX-License-Identifier: MIT
#pragma once
// A frame's colour and depth targets (rt_opaque and rt_depth in [Hathaway 2010] §3.5.1) at
// screen resolution, optionally rendered at 2x/4x MSAA and resolved with colour averaged
// and depth taking the sample closest to the observer (averaged depth would invent surfaces
// between foreground and background; §3.5.1, Cantlay). The opaque pass draws into them,
// masked-surface techniques resolve and finish them, later passes test against the depth.
#include <glm/glm.hpp>

#include "engine/render/backend.hpp"
#include "engine/render/frame_graph/color_depth.hpp"

namespace engine::render {

class FrameGraph;

struct FrameTargetsDesc {
    int width = 0;
    int height = 0;
    int samples = 1;  // 1, 2, 4 or 8 (Pure used 2; 8 where the backend has it: a2c8)
    Format colorFormat = Format::RGBA8_SRGB;
    CompareFunc depthFunc = CompareFunc::Less;
    // Which sample the MSAA depth resolves to: the closest (§3.5.1), or any one where the backend
    // cannot read samples (OpenGL ES 3.0; backend.hpp's DepthResolve).
    DepthResolve depthResolve = DepthResolve::Closest;
};

class FrameTargets {
public:
    FrameTargets(Backend& backend, const FrameTargetsDesc& desc);
    ~FrameTargets();
    FrameTargets(const FrameTargets&) = delete;
    FrameTargets& operator=(const FrameTargets&) = delete;

    // The pass to draw the opaque scene in (the MSAA targets when samples > 1), cleared to
    // `clearColor` and to the far depth of the depth function.
    PassDesc passDesc(const glm::vec4& clearColor) const;
    // The same targets loaded, not cleared: for drawing more (e.g. alpha-tested surfaces)
    // into the opaque frame before resolve().
    PassDesc loadPassDesc() const;
    // MSAA only: averages colour into rt_opaque and keeps the closest depth (or the sample
    // desc().depthResolve names) in rt_depth.
    void resolve();

    // The targets in a frame graph, imported (the graph never allocates or frees them):
    // `drawn` is what passDesc() draws into (the MSAA targets, or the resolved ones when
    // single-sampled), `resolved` is rt_opaque and rt_depth.
    struct InGraph {
        ColorDepth drawn;
        ColorDepth resolved;
    };
    InGraph importInto(FrameGraph& graph) const;
    // The pass "resolve" (MSAA only) reading `drawn` and writing `resolved`; returns the
    // resolved versions (`drawn` itself when single-sampled: nothing to do, no pass).
    ColorDepth addResolvePass(FrameGraph& graph, const ColorDepth& drawn, const ColorDepth& resolved);

    TextureHandle color() const { return color_; }  // rt_opaque
    TextureHandle depth() const { return depth_; }  // rt_depth
    const FrameTargetsDesc& desc() const { return desc_; }
    float farDepth() const;

private:
    void release();

    Backend& backend_;
    FrameTargetsDesc desc_;
    TextureHandle color_, depth_, msaaColor_, msaaDepth_;
};

}  // namespace engine::render
