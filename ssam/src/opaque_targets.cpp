// SPDX-License-Identifier: MIT
#include "ssam/opaque_targets.hpp"

#include <string>
#include <utility>

#include "engine/core/error.hpp"

namespace ssam {

using namespace engine::render;

OpaqueTargets::OpaqueTargets(Backend& backend, const OpaqueTargetsDesc& desc) : backend_(backend), desc_(desc) {
    if (desc.samples != 1 && desc.samples != 2 && desc.samples != 4)
        throw engine::Error("opaque targets: " + std::to_string(desc.samples) + " samples (use 1, 2 or 4)");
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

OpaqueTargets::~OpaqueTargets() { release(); }

void OpaqueTargets::release() {
    for (TextureHandle* t : {&color_, &depth_, &msaaColor_, &msaaDepth_})
        if (*t) backend_.destroy(std::exchange(*t, TextureHandle{}));
}

float OpaqueTargets::farDepth() const { return isCloser(desc_.depthFunc, 0.0f, 1.0f) ? 1.0f : 0.0f; }

PassDesc OpaqueTargets::passDesc(const glm::vec4& clearColor) const {
    PassDesc pass;
    pass.name = "opaque";
    pass.color[0] = {msaaColor_ ? msaaColor_ : color_, LoadOp::Clear, clearColor};
    pass.depth = {msaaDepth_ ? msaaDepth_ : depth_, LoadOp::Clear, farDepth()};
    return pass;
}

PassDesc OpaqueTargets::loadPassDesc() const {
    PassDesc pass;
    pass.name = "opaque (load)";
    pass.color[0] = {msaaColor_ ? msaaColor_ : color_, LoadOp::Load};
    pass.depth = {msaaDepth_ ? msaaDepth_ : depth_, LoadOp::Load};
    return pass;
}

void OpaqueTargets::resolve() {
    if (!msaaColor_) return;
    backend_.resolve({msaaColor_, color_, desc_.depthFunc});
    backend_.resolve({msaaDepth_, depth_, desc_.depthFunc});
}

}  // namespace ssam
