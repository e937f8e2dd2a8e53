// SPDX-License-Identifier: MIT
#pragma once
// The Vulkan host of the vk_embedding example: a plain Vulkan program not built on our engine (its
// own instance, device, queue, images and buffers), headless. It links the Vulkan loader itself,
// as an engine does; SSAM gets its vkGetInstanceProcAddr. With validation on it enables
// VK_LAYER_KHRONOS_validation with synchronization validation and counts every message.
#include <array>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

namespace vk_example {

// No Vulkan device here (or no validation layer when it is asked for): the example exits 77.
struct NoVulkan : std::runtime_error {
    using std::runtime_error::runtime_error;
};

void check(VkResult result, const char* what);  // throws std::runtime_error naming `what`

// One image memory barrier over the first level and layer of `image` (the host's images have one).
void imageBarrier(VkCommandBuffer cb, VkImage image, VkImageAspectFlags aspect, VkImageLayout from, VkImageLayout to,
                  VkPipelineStageFlags srcStages, VkAccessFlags srcAccess, VkPipelineStageFlags dstStages,
                  VkAccessFlags dstAccess);

// A graphics pipeline's two stages, each entered at "main".
std::array<VkPipelineShaderStageCreateInfo, 2> shaderStages(VkShaderModule vertex, VkShaderModule fragment);

struct HostImage {
    VkImage image = VK_NULL_HANDLE;
    VkImageView view = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    VkFormat format = VK_FORMAT_UNDEFINED;
};
struct HostBuffer {
    VkBuffer buffer = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    void* mapped = nullptr;  // host-visible, coherent, mapped for its lifetime
};

class VulkanHost {
public:
    // dynamicRendering: enable Vulkan 1.3's feature (NoVulkan where the device has not).
    // surfaceExtensions: a window's instance extensions (vk_present.hpp); given, VK_KHR_swapchain
    // is enabled too (NoVulkan where one is missing).
    // uniqueHandles false (with validation): the layer hands out the driver's own handle values
    // (VK_VALIDATION_FEATURE_DISABLE_UNIQUE_HANDLES_EXT), so an object made after one is destroyed
    // can get its value back, as without the layer; a test of what SSAM keeps by handle needs that.
    explicit VulkanHost(bool validation, bool dynamicRendering = false,
                        const std::vector<const char*>& surfaceExtensions = {}, bool uniqueHandles = true);
    ~VulkanHost();
    VulkanHost(const VulkanHost&) = delete;
    VulkanHost& operator=(const VulkanHost&) = delete;

    HostImage createImage(VkFormat format, std::uint32_t width, std::uint32_t height, VkImageUsageFlags usage,
                          VkImageAspectFlags aspect);
    HostBuffer createBuffer(VkDeviceSize size, VkBufferUsageFlags usage);  // host-visible
    // SPIR-V of `bytes` bytes; `what` names it when vkCreateShaderModule fails.
    VkShaderModule createShaderModule(const std::uint32_t* code, std::size_t bytes, const char* what) const;
    void destroy(HostImage& image);
    void destroy(HostBuffer& buffer);

    // A primary command buffer, begun (one-time submit); submit() ends it, submits it with a fence
    // (and `signal`, where one is given).
    VkCommandBuffer begin();
    VkFence submit(VkCommandBuffer commandBuffer, VkSemaphore signal = VK_NULL_HANDLE);
    void wait(VkFence fence);  // waits, then frees the fence (and its command buffer)

    VkInstance instance = VK_NULL_HANDLE;
    VkPhysicalDevice physical = VK_NULL_HANDLE;
    VkDevice device = VK_NULL_HANDLE;
    VkQueue queue = VK_NULL_HANDLE;
    std::uint32_t queueFamily = 0;
    std::uint32_t apiVersion = VK_API_VERSION_1_0;
    std::string deviceName;
    bool validation = false;
    bool dynamicRendering = false;  // the feature is enabled
    bool independentBlend = false;  // enabled (wherever the device has it)
    std::vector<std::string> validationMessages;

private:
    VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
    VkCommandPool pool_ = VK_NULL_HANDLE;
    struct InFlight {
        VkFence fence;
        VkCommandBuffer commandBuffer;
    };
    std::vector<InFlight> inFlight_;
    std::uint32_t memoryType(std::uint32_t bits, VkMemoryPropertyFlags properties) const;
    VkDeviceMemory allocate(const VkMemoryRequirements& requirements, VkMemoryPropertyFlags properties) const;
};

}  // namespace vk_example
