// SPDX-License-Identifier: MIT
#pragma once
// The Vulkan host's transparent pass (--mist), as the GL examples' HostScene::drawMist: pale mist
// over the whole frame (common/scene.hpp's kMist), alpha-blended, depth-tested against the host's
// depth without writing it -- after SSAM, a later transparent pass that sees the foliage depth
// SSAM leaves (Settings::depthMaskThreshold decides where); before SSAM, the exact answer.
#include "vk_scene.hpp"

namespace vk_example {

class MistPass {
public:
    explicit MistPass(HostScene& scene);
    ~MistPass();
    MistPass(const MistPass&) = delete;
    MistPass& operator=(const MistPass&) = delete;

    // Outside a render pass, the colour and depth in ssam::vk's contract layouts (its entry or exit
    // row: attachment writes at attachment stages), left so.
    void record(VkCommandBuffer cb) const;

private:
    HostScene& scene_;
    VkRenderPass pass_ = VK_NULL_HANDLE;
    VkFramebuffer framebuffer_ = VK_NULL_HANDLE;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    VkPipeline pipeline_ = VK_NULL_HANDLE;
};

}  // namespace vk_example
