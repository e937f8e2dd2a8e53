// SPDX-License-Identifier: MIT
#pragma once
// --present: the Vulkan examples' frames shown in a window (GLFW, no client API; on X11 an Xvfb
// display will do). Each frame then ends in vkQueuePresentKHR, the frame boundary capture tools
// count frames by (gfxreconstruct's GFXRECON_CAPTURE_FRAMES, its replay's --screenshots): without
// one a headless program is a single endless frame to them. (VK_EXT_headless_surface would need
// no display, but Debian 12's Mesa 22.3 does not offer it.) The host's colour image is blitted
// 1:1 into the acquired swapchain image after SSAM and the mist, UNORM to UNORM: bit for bit.
#include <cstdint>
#include <vector>

#include <vulkan/vulkan.h>

#include "vk_host.hpp"

struct GLFWwindow;

namespace vk_example {

// The window; made before the VulkanHost, whose instance needs its surface extensions.
class PresentWindow {
public:
    // Throws NoVulkan where GLFW cannot open a window (no display) or finds no Vulkan loader.
    PresentWindow(std::uint32_t width, std::uint32_t height, const char* title);
    ~PresentWindow();
    PresentWindow(const PresentWindow&) = delete;
    PresentWindow& operator=(const PresentWindow&) = delete;
    std::vector<const char*> instanceExtensions() const;  // VulkanHost's surfaceExtensions
    GLFWwindow* window = nullptr;
    std::uint32_t width, height;
};

// The window's surface and swapchain on the host's device.
class Presenter {
public:
    // The host must have been made with window.instanceExtensions(). Throws NoVulkan where the
    // queue cannot present or the surface offers no 8-bit UNORM format the blit can write.
    Presenter(VulkanHost& host, const PresentWindow& window);
    ~Presenter();
    Presenter(const Presenter&) = delete;
    Presenter& operator=(const Presenter&) = delete;

    // Acquires the next swapchain image (waiting on the CPU) and records into `cb` the blit of
    // `color` (COLOR_ATTACHMENT_OPTIMAL, written by attachment stages; left so) into it.
    void record(VkCommandBuffer cb, VkImage color);
    // The semaphore the submit of record()'s command buffer signals (VulkanHost::submit).
    VkSemaphore rendered() const { return rendered_[index_]; }
    // Presents the image record() acquired, after rendered().
    void present();

private:
    VulkanHost& host_;
    std::uint32_t width_, height_;
    VkSurfaceKHR surface_ = VK_NULL_HANDLE;
    VkSwapchainKHR swapchain_ = VK_NULL_HANDLE;
    std::vector<VkImage> images_;
    std::vector<VkSemaphore> rendered_;  // one per swapchain image: reused once it is acquired again
    VkFence acquired_ = VK_NULL_HANDLE;
    std::uint32_t index_ = 0;
};

}  // namespace vk_example
