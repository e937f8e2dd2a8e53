// SPDX-License-Identifier: MIT
#pragma once
// ssam::vk's own images and buffers: device memory from the host's DeviceMemoryCallbacks or one
// vkAllocateMemory each, and a list of retired objects destroyed once the frames that used them
// have completed (FrameDesc::framesCompleted).
#include <cstdint>
#include <functional>
#include <vector>

#include "vk_functions.hpp"

namespace ssam::vk::detail {

struct Memory {
    VkDeviceMemory memory = VK_NULL_HANDLE;
    VkDeviceSize offset = 0;
    bool fromHost = false;  // DeviceMemoryCallbacks::allocate gave it
};

// Device memory for SSAM's objects.
class MemorySource {
public:
    void reset(const VkFunctions& vk, VkPhysicalDevice physical, const DeviceMemoryCallbacks& host);
    Memory allocate(const VkMemoryRequirements& requirements, VkMemoryPropertyFlags properties, const char* what) const;
    void release(Memory& memory) const noexcept;

private:
    const VkFunctions* vk_ = nullptr;
    VkPhysicalDeviceMemoryProperties properties_{};
    DeviceMemoryCallbacks host_;
};

struct Image {
    VkImage image = VK_NULL_HANDLE;
    VkImageView view = VK_NULL_HANDLE;
    Memory memory;
};
// A single-sample 2D image of one level with a view of `aspect`, device-local.
Image createImage(const VkFunctions& vk, const MemorySource& memory, VkFormat format, std::uint32_t width,
                  std::uint32_t height, VkImageUsageFlags usage, const char* what,
                  VkImageAspectFlags aspect = VK_IMAGE_ASPECT_COLOR_BIT);
void destroy(const VkFunctions& vk, const MemorySource& memory, Image& image) noexcept;

struct Buffer {
    VkBuffer buffer = VK_NULL_HANDLE;
    Memory memory;
};
Buffer createBuffer(const VkFunctions& vk, const MemorySource& memory, VkDeviceSize size, VkBufferUsageFlags usage,
                    const char* what);
void destroy(const VkFunctions& vk, const MemorySource& memory, Buffer& buffer) noexcept;

// Objects replaced while frames that used them may still run: each destroyed once every frame
// up to its last use has completed.
class Retired {
public:
    void add(std::uint64_t lastUsedFrame, std::function<void()> destroy);
    void collect(std::uint64_t framesCompleted) noexcept;  // frames below framesCompleted are done
    void destroyAll() noexcept;                            // the device is idle

private:
    struct Entry {
        std::uint64_t lastUsedFrame;
        std::function<void()> destroy;
    };
    std::vector<Entry> entries_;
};

}  // namespace ssam::vk::detail
