// SPDX-License-Identifier: MIT
#include "resources.hpp"

#include <string>

#include "failure.hpp"

namespace ssam::vk::detail {

void MemorySource::reset(const VkFunctions& vk, VkPhysicalDevice physical, const DeviceMemoryCallbacks& host) {
    vk_ = &vk;
    vk.GetPhysicalDeviceMemoryProperties(physical, &properties_);
    host_ = host;
}

Memory MemorySource::allocate(const VkMemoryRequirements& requirements, VkMemoryPropertyFlags properties,
                              const char* what) const {
    Memory out;
    if (host_.allocate) {
        check(host_.allocate(host_.user, requirements, properties, &out.memory, &out.offset),
              (std::string("the host's DeviceMemoryCallbacks::allocate for ") + what).c_str());
        if (out.memory == VK_NULL_HANDLE || out.offset % requirements.alignment != 0)
            throw Failure(Status::InvalidArgument, std::string("ssam::vk: the host's DeviceMemoryCallbacks::allocate "
                                                               "gave no memory or a misaligned offset for ") +
                                                       what);
        out.fromHost = true;
        return out;
    }
    std::uint32_t type = properties_.memoryTypeCount;
    for (std::uint32_t i = 0; i < properties_.memoryTypeCount && type == properties_.memoryTypeCount; ++i)
        if ((requirements.memoryTypeBits & (1u << i)) &&
            (properties_.memoryTypes[i].propertyFlags & properties) == properties)
            type = i;
    if (type == properties_.memoryTypeCount)
        throw Failure(Status::UnsupportedFeature, std::string("ssam::vk: no memory type for ") + what);
    VkMemoryAllocateInfo info{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    info.allocationSize = requirements.size;
    info.memoryTypeIndex = type;
    check(vk_->AllocateMemory(vk_->device, &info, vk_->allocator, &out.memory),
          (std::string("vkAllocateMemory for ") + what).c_str());
    return out;
}

void MemorySource::release(Memory& memory) const noexcept {
    if (memory.memory == VK_NULL_HANDLE) return;
    if (memory.fromHost) host_.release(host_.user, memory.memory, memory.offset);
    else vk_->FreeMemory(vk_->device, memory.memory, vk_->allocator);
    memory = {};
}

namespace {

// `make(out)` creates a resource into `out`; when it throws, what it made so far is destroyed.
template <class Resource, class Make>
Resource createOrUndo(const VkFunctions& vk, const MemorySource& memory, Make&& make) {
    Resource out;
    try {
        make(out);
    } catch (...) {
        destroy(vk, memory, out);
        throw;
    }
    return out;
}

// Device-local memory for the resource, bound to it; kept in `out` first, so that createOrUndo
// gives it back when binding fails.
void allocateAndBind(const VkFunctions& vk, const MemorySource& memory, Image& out, const char* what) {
    VkMemoryRequirements requirements;
    vk.GetImageMemoryRequirements(vk.device, out.image, &requirements);
    out.memory = memory.allocate(requirements, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, what);
    check(vk.BindImageMemory(vk.device, out.image, out.memory.memory, out.memory.offset), "vkBindImageMemory");
}

void allocateAndBind(const VkFunctions& vk, const MemorySource& memory, Buffer& out, const char* what) {
    VkMemoryRequirements requirements;
    vk.GetBufferMemoryRequirements(vk.device, out.buffer, &requirements);
    out.memory = memory.allocate(requirements, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, what);
    check(vk.BindBufferMemory(vk.device, out.buffer, out.memory.memory, out.memory.offset), "vkBindBufferMemory");
}

}  // namespace

Image createImage(const VkFunctions& vk, const MemorySource& memory, VkFormat format, std::uint32_t width,
                  std::uint32_t height, VkImageUsageFlags usage, const char* what, VkImageAspectFlags aspect) {
    return createOrUndo<Image>(vk, memory, [&](Image& out) {
        VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
        info.imageType = VK_IMAGE_TYPE_2D;
        info.format = format;
        info.extent = {width, height, 1};
        info.mipLevels = 1;
        info.arrayLayers = 1;
        info.samples = VK_SAMPLE_COUNT_1_BIT;
        info.tiling = VK_IMAGE_TILING_OPTIMAL;
        info.usage = usage;
        info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
        info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
        check(vk.CreateImage(vk.device, &info, vk.allocator, &out.image), "vkCreateImage", what);
        allocateAndBind(vk, memory, out, what);
        VkImageViewCreateInfo view{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
        view.image = out.image;
        view.viewType = VK_IMAGE_VIEW_TYPE_2D;
        view.format = format;
        view.subresourceRange = {aspect, 0, 1, 0, 1};
        check(vk.CreateImageView(vk.device, &view, vk.allocator, &out.view), "vkCreateImageView", what);
    });
}

void destroy(const VkFunctions& vk, const MemorySource& memory, Image& image) noexcept {
    if (image.view) vk.DestroyImageView(vk.device, image.view, vk.allocator);
    if (image.image) vk.DestroyImage(vk.device, image.image, vk.allocator);
    memory.release(image.memory);
    image = {};
}

Buffer createBuffer(const VkFunctions& vk, const MemorySource& memory, VkDeviceSize size, VkBufferUsageFlags usage,
                    const char* what) {
    return createOrUndo<Buffer>(vk, memory, [&](Buffer& out) {
        VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
        info.size = size;
        info.usage = usage;
        info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
        check(vk.CreateBuffer(vk.device, &info, vk.allocator, &out.buffer), "vkCreateBuffer", what);
        allocateAndBind(vk, memory, out, what);
    });
}

void destroy(const VkFunctions& vk, const MemorySource& memory, Buffer& buffer) noexcept {
    if (buffer.buffer) vk.DestroyBuffer(vk.device, buffer.buffer, vk.allocator);
    memory.release(buffer.memory);
    buffer = {};
}

void Retired::add(std::uint64_t lastUsedFrame, std::function<void()> destroy) {
    entries_.push_back({lastUsedFrame, std::move(destroy)});
}

void Retired::collect(std::uint64_t framesCompleted) noexcept {
    std::size_t kept = 0;
    for (Entry& e : entries_) {
        if (e.lastUsedFrame < framesCompleted) e.destroy();
        else if (&entries_[kept++] != &e) entries_[kept - 1] = std::move(e);
    }
    entries_.resize(kept);
}

void Retired::destroyAll() noexcept {
    for (Entry& e : entries_) e.destroy();
    entries_.clear();
}

}  // namespace ssam::vk::detail
