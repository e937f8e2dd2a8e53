// SPDX-License-Identifier: MIT
// The window's swapchain (vk_swapchain.hpp) and the Vulkan driver's present: the frame's colour is
// blitted into the acquired image by a submission that waits for the acquire and signals the
// presentation.
#include "vk_swapchain.hpp"

#include <algorithm>

#include "engine/core/error.hpp"
#include "engine/render/vk/vk_window.hpp"
#include "vk_backend_impl.hpp"

namespace engine::render::vk {
namespace {

VkSemaphore newSemaphore(VkDevice device) {
    VkSemaphoreCreateInfo ci{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
    VkSemaphore s = VK_NULL_HANDLE;
    check(vkCreateSemaphore(device, &ci, nullptr, &s), "Vulkan backend: a swapchain semaphore");
    return s;
}

// An 8-bit BGRA or RGBA format in the sRGB colour space, sRGB-encoded or not as asked; else the first.
VkSurfaceFormatKHR chooseFormat(const std::vector<VkSurfaceFormatKHR>& formats, bool srgb) {
    for (const VkSurfaceFormatKHR& f : formats) {
        if (f.colorSpace != VK_COLOR_SPACE_SRGB_NONLINEAR_KHR) continue;
        if (srgb && (f.format == VK_FORMAT_B8G8R8A8_SRGB || f.format == VK_FORMAT_R8G8B8A8_SRGB)) return f;
        if (!srgb && (f.format == VK_FORMAT_B8G8R8A8_UNORM || f.format == VK_FORMAT_R8G8B8A8_UNORM)) return f;
    }
    return formats.front();
}

}  // namespace

Swapchain::Swapchain(VulkanContext& context, VulkanCounters& counters, std::size_t frameSlots)
    : context_(context), counters_(counters) {
    for (std::size_t i = 0; i < frameSlots; ++i) acquired_.push_back(newSemaphore(context_.device));
}

Swapchain::~Swapchain() {
    destroyImages();
    if (swapchain_) vkDestroySwapchainKHR(context_.device, swapchain_, nullptr);
    for (VkSemaphore s : acquired_) vkDestroySemaphore(context_.device, s, nullptr);
}

void Swapchain::destroyImages() {
    for (VkSemaphore s : presentable_) vkDestroySemaphore(context_.device, s, nullptr);
    presentable_.clear();
    images_.clear();  // the swapchain owns them
}

bool Swapchain::recreate(glm::ivec2 size, bool srgb) {
    // Nothing submitted may still use the old images or semaphores: a resize is no steady frame.
    check(vkDeviceWaitIdle(context_.device), "Vulkan backend: waiting before remaking the swapchain");
    VkSurfaceCapabilitiesKHR caps;
    check(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(context_.physical, context_.surface, &caps),
          "Vulkan backend: the window surface's capabilities");
    VkExtent2D extent = caps.currentExtent;
    if (extent.width == 0xFFFFFFFFu) {  // the surface takes the swapchain's size: the framebuffer's
        extent.width = std::clamp(std::uint32_t(size.x), caps.minImageExtent.width, caps.maxImageExtent.width);
        extent.height = std::clamp(std::uint32_t(size.y), caps.minImageExtent.height, caps.maxImageExtent.height);
    }
    if (extent.width == 0 || extent.height == 0) return false;  // minimised: try again at the next frame
    if (!(caps.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_DST_BIT))
        throw Error("Vulkan backend: the window's swapchain images cannot be blitted into (no TRANSFER_DST usage)");
    std::uint32_t count = 0;
    vkGetPhysicalDeviceSurfaceFormatsKHR(context_.physical, context_.surface, &count, nullptr);
    std::vector<VkSurfaceFormatKHR> formats(count);
    vkGetPhysicalDeviceSurfaceFormatsKHR(context_.physical, context_.surface, &count, formats.data());
    if (formats.empty()) throw Error("Vulkan backend: the window surface offers no format");
    const VkSurfaceFormatKHR format = chooseFormat(formats, srgb);

    VkSwapchainCreateInfoKHR ci{VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR};
    ci.surface = context_.surface;
    // One more than the least, so acquiring rarely waits for the display to release one.
    ci.minImageCount = caps.minImageCount + 1;
    if (caps.maxImageCount > 0) ci.minImageCount = std::min(ci.minImageCount, caps.maxImageCount);
    ci.imageFormat = format.format;
    ci.imageColorSpace = format.colorSpace;
    ci.imageExtent = extent;
    ci.imageArrayLayers = 1;
    ci.imageUsage = VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    ci.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE;
    ci.preTransform = (caps.supportedTransforms & VK_SURFACE_TRANSFORM_IDENTITY_BIT_KHR)
                          ? VK_SURFACE_TRANSFORM_IDENTITY_BIT_KHR
                          : caps.currentTransform;
    ci.compositeAlpha = VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR;
    for (VkCompositeAlphaFlagBitsKHR a :
         {VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR, VK_COMPOSITE_ALPHA_INHERIT_BIT_KHR,
          VK_COMPOSITE_ALPHA_PRE_MULTIPLIED_BIT_KHR, VK_COMPOSITE_ALPHA_POST_MULTIPLIED_BIT_KHR})
        if (caps.supportedCompositeAlpha & a) {
            ci.compositeAlpha = a;
            break;
        }
    ci.presentMode = VK_PRESENT_MODE_FIFO_KHR;  // always supported
    ci.clipped = VK_TRUE;
    ci.oldSwapchain = swapchain_;
    VkSwapchainKHR made = VK_NULL_HANDLE;
    check(vkCreateSwapchainKHR(context_.device, &ci, nullptr, &made),
          "Vulkan backend: a " + std::to_string(extent.width) + "x" + std::to_string(extent.height) + " swapchain");
    destroyImages();
    if (swapchain_) vkDestroySwapchainKHR(context_.device, swapchain_, nullptr);
    swapchain_ = made;
    ++counters_.swapchainsCreated;
    vkGetSwapchainImagesKHR(context_.device, swapchain_, &count, nullptr);
    images_.resize(count);
    vkGetSwapchainImagesKHR(context_.device, swapchain_, &count, images_.data());
    for (std::uint32_t i = 0; i < count; ++i) presentable_.push_back(newSemaphore(context_.device));
    format_ = format.format;
    extent_ = extent;
    madeFor_ = size;
    srgb_ = srgb;
    stale_ = false;
    return true;
}

std::optional<SwapchainImage> Swapchain::acquire(glm::ivec2 size, std::size_t slot, bool srgb) {
    if ((stale_ || size != madeFor_ || srgb != srgb_) && !recreate(size, srgb)) return std::nullopt;
    SwapchainImage image;
    image.acquired = acquired_[slot];
    const VkResult r =
        vkAcquireNextImageKHR(context_.device, swapchain_, UINT64_MAX, image.acquired, VK_NULL_HANDLE, &image.index);
    if (r == VK_ERROR_OUT_OF_DATE_KHR) {  // nothing was acquired, the semaphore stays unsignalled
        stale_ = true;
        return std::nullopt;
    }
    if (r == VK_SUBOPTIMAL_KHR) stale_ = true;  // acquired and usable: shown, then remade
    else check(r, "Vulkan backend: acquiring a swapchain image");
    image.image = images_[image.index];
    image.presentable = presentable_[image.index];
    return image;
}

void Swapchain::present(const SwapchainImage& image) {
    VkPresentInfoKHR pi{VK_STRUCTURE_TYPE_PRESENT_INFO_KHR};
    pi.waitSemaphoreCount = 1;
    pi.pWaitSemaphores = &image.presentable;
    pi.swapchainCount = 1;
    pi.pSwapchains = &swapchain_;
    pi.pImageIndices = &image.index;
    const VkResult r = vkQueuePresentKHR(context_.queue, &pi);
    // Out of date or suboptimal: the image's semaphore wait still happened; remade next time.
    if (r == VK_ERROR_OUT_OF_DATE_KHR || r == VK_SUBOPTIMAL_KHR) stale_ = true;
    else check(r, "Vulkan backend: presenting a swapchain image");
    ++counters_.framesPresented;
}

bool VulkanDriverImpl::present(NativeId h, const TextureDesc&) {
    VulkanTexture& t = textures_[h];
    const std::string name = quotedName(t.desc.name);
    if (!swapchain_) throw Error("present of " + name + ": the Vulkan backend has no window (VulkanOptions::window)");
    const FormatInfo info = formatInfo(t.desc.format);
    const glm::ivec2 size = options_.window->framebufferSize();
    if (size.x <= 0 || size.y <= 0) return false;  // minimised: nothing to show
    const VkCommandBuffer cmd = frames_->cmd();    // waits for the slot, so its semaphore is free
    const std::optional<SwapchainImage> image = swapchain_->acquire(size, frames_->slot(), info.isSrgb);
    if (!image) return false;  // what is recorded goes with the next submission

    use(cmd, t, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT,
        false);
    VkImageMemoryBarrier b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
    b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    b.image = image->image;
    b.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    // From the acquire (the submission waits for its semaphore at the transfer stage): the old
    // contents are not needed.
    b.oldLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    b.newLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
    b.dstAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0, nullptr, 0, nullptr,
                         1, &b);
    const VkExtent2D extent = swapchain_->extent();
    VkImageBlit blit{};
    blit.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    blit.srcOffsets[1] = {t.desc.width, t.desc.height, 1};
    blit.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    blit.dstOffsets[1] = {std::int32_t(extent.width), std::int32_t(extent.height), 1};
    const bool same = extent.width == std::uint32_t(t.desc.width) && extent.height == std::uint32_t(t.desc.height);
    // Row 0 is the top of both (the negative-height viewport), so no flip, unlike GL's present.
    vkCmdBlitImage(cmd, t.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, image->image,
                   VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &blit, same ? VK_FILTER_NEAREST : VK_FILTER_LINEAR);
    b.oldLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
    b.newLayout = VK_IMAGE_LAYOUT_PRESENT_SRC_KHR;
    b.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    b.dstAccessMask = 0;  // presentation's visibility comes with the semaphore
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, 0, 0, nullptr, 0,
                         nullptr, 1, &b);
    frames_->submit(false, image->acquired, VK_PIPELINE_STAGE_TRANSFER_BIT, image->presentable);
    swapchain_->present(*image);
    return true;
}

}  // namespace engine::render::vk
