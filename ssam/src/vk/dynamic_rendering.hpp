// SPDX-License-Identifier: MIT
#pragma once
// RenderingPath::DynamicRendering: SSAM's three passes with vkCmdBeginRendering, and pipeline
// barriers of the same stages, accesses and layout transitions as the render-pass path's
// VkSubpassDependency / attachment layouts (pipelines.cpp's createRenderPass), so both paths keep
// the one synchronization contract of ssam_vk.hpp.
#include "pipelines.hpp"

namespace ssam::vk::detail {

struct DynamicPassTargets {
    VkImageView hostColor = VK_NULL_HANDLE, hostDepth = VK_NULL_HANDLE;
    VkFormat depthFormat = VK_FORMAT_UNDEFINED;
    std::uint32_t width = 0, height = 0;
};

// The barrier in, then vkCmdBeginRendering (colour cleared to `clear` for the mask and colour
// passes, the host's depth and stencil loaded and stored; the composite loads the host's colour).
void beginDynamicPass(const VkFunctions& vk, VkCommandBuffer cb, PassKind pass, const Generation& g,
                      const DynamicPassTargets& targets, const VkClearValue* clear);
// vkCmdEndRendering, then the barrier out.
void endDynamicPass(const VkFunctions& vk, VkCommandBuffer cb, PassKind pass, const Generation& g);

}  // namespace ssam::vk::detail
