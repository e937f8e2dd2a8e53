// SPDX-License-Identifier: MIT
#pragma once
// The Vulkan entry points ssam::vk calls, resolved through the host's vkGetInstanceProcAddr /
// vkGetDeviceProcAddr (ssam_vk links no Vulkan library; its sources build with VK_NO_PROTOTYPES).
#include "ssam/vk/ssam_vk.hpp"

namespace ssam::vk::detail {

#define SSAM_VK_INSTANCE_FUNCTIONS(X)    \
    X(GetPhysicalDeviceMemoryProperties) \
    X(GetPhysicalDeviceFormatProperties) \
    X(GetPhysicalDeviceProperties)

#define SSAM_VK_DEVICE_FUNCTIONS(X) \
    X(CreateShaderModule)           \
    X(DestroyShaderModule)          \
    X(CreatePipelineLayout)         \
    X(DestroyPipelineLayout)        \
    X(CreateDescriptorSetLayout)    \
    X(DestroyDescriptorSetLayout)   \
    X(CreateDescriptorPool)         \
    X(DestroyDescriptorPool)        \
    X(AllocateDescriptorSets)       \
    X(FreeDescriptorSets)           \
    X(UpdateDescriptorSets)         \
    X(CreateSampler)                \
    X(DestroySampler)               \
    X(CreateRenderPass)             \
    X(DestroyRenderPass)            \
    X(CreateGraphicsPipelines)      \
    X(DestroyPipeline)              \
    X(CreateFramebuffer)            \
    X(DestroyFramebuffer)           \
    X(CreateImage)                  \
    X(DestroyImage)                 \
    X(CreateImageView)              \
    X(DestroyImageView)             \
    X(CreateBuffer)                 \
    X(DestroyBuffer)                \
    X(GetImageMemoryRequirements)   \
    X(GetBufferMemoryRequirements)  \
    X(AllocateMemory)               \
    X(FreeMemory)                   \
    X(BindImageMemory)              \
    X(BindBufferMemory)             \
    X(CmdPipelineBarrier)           \
    X(CmdUpdateBuffer)              \
    X(CmdClearColorImage)           \
    X(CmdCopyImage)                 \
    X(CmdBeginRenderPass)           \
    X(CmdEndRenderPass)             \
    X(CmdBindPipeline)              \
    X(CmdBindDescriptorSets)        \
    X(CmdBindVertexBuffers)         \
    X(CmdPushConstants)             \
    X(CmdSetViewport)               \
    X(CmdSetScissor)                \
    X(CmdDraw)

struct VkFunctions {
#define SSAM_VK_MEMBER(name) PFN_vk##name name = nullptr;
    SSAM_VK_INSTANCE_FUNCTIONS(SSAM_VK_MEMBER)
    SSAM_VK_DEVICE_FUNCTIONS(SSAM_VK_MEMBER)
#undef SSAM_VK_MEMBER
    // RenderingPath::DynamicRendering only: Vulkan 1.3's, else VK_KHR_dynamic_rendering's.
    PFN_vkCmdBeginRendering CmdBeginRendering = nullptr;
    PFN_vkCmdEndRendering CmdEndRendering = nullptr;
    VkDevice device = VK_NULL_HANDLE;
    const VkAllocationCallbacks* allocator = nullptr;
};

// Every entry point above (and the dynamic-rendering ones when DeviceDesc asks for that path), or
// MissingEntryPoint naming the first the host's loader has not.
void loadFunctions(VkFunctions& vk, const DeviceDesc& desc);

}  // namespace ssam::vk::detail
