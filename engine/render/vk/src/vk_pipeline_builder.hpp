// SPDX-License-Identifier: MIT
#pragma once
// One graphics pipeline from the parts in which the backend's pipelines differ (a program's,
// made from resolved state, and the resolves'); the rest is fixed here once: triangle lists,
// filled polygons, line width 1, and one viewport and scissor set per draw (dynamic state).
#include <span>
#include <string>

#include <vulkan/vulkan.h>

namespace engine::render::vk {

struct GraphicsPipelineParts {
    VkShaderModule vertex = VK_NULL_HANDLE;
    VkShaderModule fragment = VK_NULL_HANDLE;
    std::span<const VkVertexInputBindingDescription> bindings;  // none: full-screen, no vertex input
    std::span<const VkVertexInputAttributeDescription> attributes;
    VkCullModeFlags cull = VK_CULL_MODE_NONE;
    VkFrontFace frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
    VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
    bool depthTest = false;
    bool depthWrite = false;
    VkCompareOp depthCompare = VK_COMPARE_OP_ALWAYS;
    std::span<const VkPipelineColorBlendAttachmentState> blends;  // one per colour attachment
    bool dynamicBlendConstants = false;
    VkPipelineLayout layout = VK_NULL_HANDLE;
    VkRenderPass renderPass = VK_NULL_HANDLE;  // any pass compatible with the ones it runs in
};

// Throws engine::Error starting with `what` when Vulkan refuses.
VkPipeline createGraphicsPipeline(VkDevice device, const GraphicsPipelineParts& parts, const std::string& what);

}  // namespace engine::render::vk
