// SPDX-License-Identifier: MIT
#pragma once
// The opaque pass's targets ([Hathaway 2010] §3.5.1): rt_opaque and rt_depth at screen
// resolution, optionally rendered at 2x/4x MSAA and resolved with colour averaged and
// depth taking the sample closest to the observer (averaged depth would invent surfaces
// between foreground and background; §3.5.1, Cantlay).
#include <glm/glm.hpp>

#include "engine/render/backend.hpp"

namespace ssam {

struct OpaqueTargetsDesc {
    int width = 0;
    int height = 0;
    int samples = 1;  // 1, 2 or 4 (Pure used 2)
    engine::render::Format colorFormat = engine::render::Format::RGBA8_SRGB;
    engine::render::CompareFunc depthFunc = engine::render::CompareFunc::Less;
};

class OpaqueTargets {
public:
    OpaqueTargets(engine::render::Backend& backend, const OpaqueTargetsDesc& desc);
    ~OpaqueTargets();
    OpaqueTargets(const OpaqueTargets&) = delete;
    OpaqueTargets& operator=(const OpaqueTargets&) = delete;

    // The pass to draw the opaque scene in (the MSAA targets when samples > 1), cleared to
    // `clearColor` and to the far depth of the depth function.
    engine::render::PassDesc passDesc(const glm::vec4& clearColor) const;
    // The same targets loaded, not cleared: for drawing more (e.g. alpha-tested foliage)
    // into the opaque frame before resolve().
    engine::render::PassDesc loadPassDesc() const;
    // MSAA only: averages colour into rt_opaque and keeps the closest depth in rt_depth.
    void resolve();

    engine::render::TextureHandle color() const { return color_; }  // rt_opaque
    engine::render::TextureHandle depth() const { return depth_; }  // rt_depth
    const OpaqueTargetsDesc& desc() const { return desc_; }
    float farDepth() const;

private:
    void release();

    engine::render::Backend& backend_;
    OpaqueTargetsDesc desc_;
    engine::render::TextureHandle color_, depth_, msaaColor_, msaaDepth_;
};

}  // namespace ssam
