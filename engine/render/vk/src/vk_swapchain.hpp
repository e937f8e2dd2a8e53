// SPDX-License-Identifier: MIT
#pragma once
// The window's swapchain (VulkanOptions::window): FIFO presentation (the one mode every device
// offers), images the frame's colour is blitted into. An acquire semaphore per frame slot (free
// once the slot's fence has signalled, so cmd() must have begun the slot before acquire) and a
// present semaphore per swapchain image (free once that image is acquired again). Made anew,
// after vkDeviceWaitIdle (the only place besides tear-down), when the window's framebuffer size
// changes or the surface reports the swapchain out of date or suboptimal.
#include <cstdint>
#include <optional>
#include <vector>

#include <glm/vec2.hpp>
#include <vulkan/vulkan.h>

#include "engine/render/vk/vk_backend.hpp"
#include "vk_context.hpp"

namespace engine::render::vk {

struct SwapchainImage {
    std::uint32_t index = 0;
    VkImage image = VK_NULL_HANDLE;
    VkSemaphore acquired = VK_NULL_HANDLE;     // the blit's submission waits for it
    VkSemaphore presentable = VK_NULL_HANDLE;  // the blit's submission signals it, presenting waits
};

class Swapchain {
public:
    Swapchain(VulkanContext& context, VulkanCounters& counters, std::size_t frameSlots);
    ~Swapchain();
    Swapchain(const Swapchain&) = delete;
    Swapchain& operator=(const Swapchain&) = delete;

    // The next image for a window whose framebuffer is `size` (not empty), with frame slot
    // `slot`'s acquire semaphore, in an sRGB format when `srgb` (so a blit keeps the stored
    // codes of an sRGB source, and of a linear one with a linear format, as GL's present does); nullopt when the swapchain was out of date (it is made anew
    // for the next call) or the surface is empty now.
    std::optional<SwapchainImage> acquire(glm::ivec2 size, std::size_t slot, bool srgb);
    // Queues the image for presentation; an out of date or suboptimal result makes the next
    // acquire remake the swapchain.
    void present(const SwapchainImage& image);

    VkFormat format() const { return format_; }
    VkExtent2D extent() const { return extent_; }

private:
    bool recreate(glm::ivec2 size, bool srgb);  // false when the surface is empty (minimised)
    void destroyImages();

    VulkanContext& context_;
    VulkanCounters& counters_;
    VkSwapchainKHR swapchain_ = VK_NULL_HANDLE;
    VkFormat format_ = VK_FORMAT_UNDEFINED;
    VkExtent2D extent_{0, 0};
    glm::ivec2 madeFor_{0, 0};  // the framebuffer size it was made for
    bool stale_ = true;
    bool srgb_ = true;
    std::vector<VkImage> images_;
    std::vector<VkSemaphore> acquired_;     // per frame slot
    std::vector<VkSemaphore> presentable_;  // per image
};

}  // namespace engine::render::vk
