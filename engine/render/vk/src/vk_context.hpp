// SPDX-License-Identifier: MIT
#pragma once
// The Vulkan instance, the debug messenger that makes validation a test oracle, the chosen
// physical device and its logical device with one graphics queue. Owned by the backend and
// destroyed last.
#include <cstdint>
#include <functional>
#include <string>

#include <vulkan/vulkan.h>

#include "engine/render/vk/vk_backend.hpp"

namespace engine::render::vk {

struct VulkanContext {
    VkInstance instance = VK_NULL_HANDLE;
    VkDebugUtilsMessengerEXT messenger = VK_NULL_HANDLE;
    VkPhysicalDevice physical = VK_NULL_HANDLE;
    VkSurfaceKHR surface = VK_NULL_HANDLE;  // VulkanOptions::window's, when there is one
    VkDevice device = VK_NULL_HANDLE;
    VkQueue queue = VK_NULL_HANDLE;
    std::uint32_t queueFamily = 0;
    std::uint32_t timestampValidBits = 0;  // of the queue family's timestamps (0: none)
    VkPhysicalDeviceProperties properties{};
    VkPhysicalDeviceMemoryProperties memory{};
    bool conditionalRendering = false;  // VK_EXT_conditional_rendering enabled
    VulkanInfo info;
    std::uint64_t validationMessages = 0;
    std::function<void(const std::string&)> onValidation;

    // Throws engine::Error saying what is missing; nothing is left created then.
    static std::unique_ptr<VulkanContext> create(const VulkanOptions& options);
    ~VulkanContext();

    // A memory type among `typeBits` with `wanted` properties; throws when none.
    std::uint32_t memoryType(std::uint32_t typeBits, VkMemoryPropertyFlags wanted, const std::string& what) const;
};

// Throws engine::Error naming `what` and the VkResult when `result` is not VK_SUCCESS, with
// vulkanResultMessage's words (vk_results.hpp): a lost device is named as such. Every submit,
// fence wait, query-result read, acquire and present goes through it.
void check(VkResult result, const std::string& what);
const char* resultName(VkResult result);

}  // namespace engine::render::vk
