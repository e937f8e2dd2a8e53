// SPDX-License-Identifier: MIT
#include "vk_present.hpp"

#include <algorithm>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "vk_scene.hpp"  // imageBarrier

namespace vk_example {

PresentWindow::PresentWindow(std::uint32_t w, std::uint32_t h, const char* title) : width(w), height(h) {
    if (!glfwInit()) throw NoVulkan("--present: GLFW cannot initialise (no display?)");
    if (!glfwVulkanSupported()) {
        glfwTerminate();
        throw NoVulkan("--present: GLFW finds no Vulkan loader");
    }
    glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
    glfwWindowHint(GLFW_RESIZABLE, GLFW_FALSE);
    window = glfwCreateWindow(int(w), int(h), title, nullptr, nullptr);
    if (!window) {
        glfwTerminate();
        throw NoVulkan("--present: GLFW cannot open a window");
    }
}

PresentWindow::~PresentWindow() {
    glfwDestroyWindow(window);
    glfwTerminate();
}

std::vector<const char*> PresentWindow::instanceExtensions() const {
    std::uint32_t count = 0;
    const char** names = glfwGetRequiredInstanceExtensions(&count);
    if (!names) throw NoVulkan("--present: GLFW names no Vulkan surface extensions");
    return {names, names + count};
}

Presenter::Presenter(VulkanHost& host, const PresentWindow& window)
    : host_(host), width_(window.width), height_(window.height) {
    check(glfwCreateWindowSurface(host.instance, window.window, nullptr, &surface_), "glfwCreateWindowSurface");
    VkBool32 supported = VK_FALSE;
    check(vkGetPhysicalDeviceSurfaceSupportKHR(host.physical, host.queueFamily, surface_, &supported),
          "vkGetPhysicalDeviceSurfaceSupportKHR");
    if (!supported) throw NoVulkan("--present: the graphics queue cannot present to the window");
    VkSurfaceCapabilitiesKHR caps;
    check(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(host.physical, surface_, &caps),
          "vkGetPhysicalDeviceSurfaceCapabilitiesKHR");
    if (!(caps.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_DST_BIT))
        throw NoVulkan("--present: the swapchain's images cannot be blitted to");
    std::uint32_t count = 0;
    vkGetPhysicalDeviceSurfaceFormatsKHR(host.physical, surface_, &count, nullptr);
    std::vector<VkSurfaceFormatKHR> formats(count);
    vkGetPhysicalDeviceSurfaceFormatsKHR(host.physical, surface_, &count, formats.data());
    // UNORM, not sRGB: the blit then copies the colour image's codes unchanged.
    const auto format = std::find_if(formats.begin(), formats.end(), [](const VkSurfaceFormatKHR& f) {
        return f.format == VK_FORMAT_B8G8R8A8_UNORM || f.format == VK_FORMAT_R8G8B8A8_UNORM;
    });
    if (format == formats.end()) throw NoVulkan("--present: the surface offers no 8-bit UNORM format");
    VkSwapchainCreateInfoKHR info{VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR};
    info.surface = surface_;
    // Three images for the examples' two frames in flight.
    info.minImageCount = std::max(caps.minImageCount, 3u);
    if (caps.maxImageCount) info.minImageCount = std::min(info.minImageCount, caps.maxImageCount);
    info.imageFormat = format->format;
    info.imageColorSpace = format->colorSpace;
    info.imageExtent = {width_, height_};
    info.imageArrayLayers = 1;
    info.imageUsage = VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    info.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE;
    info.preTransform = VK_SURFACE_TRANSFORM_IDENTITY_BIT_KHR;
    info.compositeAlpha = VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR;
    info.presentMode = VK_PRESENT_MODE_FIFO_KHR;  // the one every surface has
    info.clipped = VK_TRUE;
    check(vkCreateSwapchainKHR(host.device, &info, nullptr, &swapchain_), "vkCreateSwapchainKHR");
    vkGetSwapchainImagesKHR(host.device, swapchain_, &count, nullptr);
    images_.resize(count);
    vkGetSwapchainImagesKHR(host.device, swapchain_, &count, images_.data());
    rendered_.resize(count);
    const VkSemaphoreCreateInfo semaphore{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
    for (VkSemaphore& s : rendered_)
        check(vkCreateSemaphore(host.device, &semaphore, nullptr, &s), "vkCreateSemaphore");
    const VkFenceCreateInfo fence{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    check(vkCreateFence(host.device, &fence, nullptr, &acquired_), "vkCreateFence");
}

Presenter::~Presenter() {
    vkDeviceWaitIdle(host_.device);
    vkDestroyFence(host_.device, acquired_, nullptr);
    for (VkSemaphore s : rendered_) vkDestroySemaphore(host_.device, s, nullptr);
    vkDestroySwapchainKHR(host_.device, swapchain_, nullptr);
    vkDestroySurfaceKHR(host_.instance, surface_, nullptr);
}

void Presenter::record(VkCommandBuffer cb, VkImage color) {
    // Acquired with a fence waited here: the blit below then needs no acquire semaphore.
    check(vkAcquireNextImageKHR(host_.device, swapchain_, UINT64_MAX, VK_NULL_HANDLE, acquired_, &index_),
          "vkAcquireNextImageKHR");
    check(vkWaitForFences(host_.device, 1, &acquired_, VK_TRUE, UINT64_MAX), "vkWaitForFences");
    check(vkResetFences(host_.device, 1, &acquired_), "vkResetFences");
    const VkImage target = images_[index_];
    imageBarrier(cb, color, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                 VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                 VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT);
    imageBarrier(cb, target, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                 VK_PIPELINE_STAGE_TRANSFER_BIT, 0, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT);
    VkImageBlit region{};
    region.srcSubresource = region.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.srcOffsets[1] = region.dstOffsets[1] = {std::int32_t(width_), std::int32_t(height_), 1};
    vkCmdBlitImage(cb, color, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, target, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1,
                   &region, VK_FILTER_NEAREST);
    imageBarrier(cb, target, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                 VK_IMAGE_LAYOUT_PRESENT_SRC_KHR, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
                 VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, 0);
    // Back to what the next frame's opaque pass and the readback expect of the colour image.
    imageBarrier(cb, color, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                 VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_TRANSFER_BIT, 0,
                 VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                 VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT);
}

void Presenter::present() {
    VkPresentInfoKHR info{VK_STRUCTURE_TYPE_PRESENT_INFO_KHR};
    info.waitSemaphoreCount = 1;
    info.pWaitSemaphores = &rendered_[index_];
    info.swapchainCount = 1;
    info.pSwapchains = &swapchain_;
    info.pImageIndices = &index_;
    check(vkQueuePresentKHR(host_.queue, &info), "vkQueuePresentKHR");
}

}  // namespace vk_example
