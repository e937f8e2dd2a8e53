// SPDX-License-Identifier: MIT
#include "vk_frames.hpp"

#include <algorithm>

#include "engine/core/error.hpp"

namespace engine::render::vk {
namespace {

constexpr std::uint64_t kChunkBytes = 4u << 20;  // grows to fit a larger request
constexpr std::uint32_t kSetsPerPool = 256;

}  // namespace

MemoryBuffer createHostBuffer(const VulkanContext& context, std::uint64_t size, VkBufferUsageFlags usage,
                              const std::string& what) {
    MemoryBuffer b;
    VkBufferCreateInfo ci{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    ci.size = size;
    ci.usage = usage;
    ci.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    check(vkCreateBuffer(context.device, &ci, nullptr, &b.buffer), what + ": creating a buffer");
    try {
        VkMemoryRequirements req;
        vkGetBufferMemoryRequirements(context.device, b.buffer, &req);
        VkMemoryAllocateInfo ai{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
        ai.allocationSize = req.size;
        ai.memoryTypeIndex = context.memoryType(
            req.memoryTypeBits, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT, what);
        check(vkAllocateMemory(context.device, &ai, nullptr, &b.memory),
              what + ": allocating " + std::to_string(size) + " bytes");
        check(vkBindBufferMemory(context.device, b.buffer, b.memory, 0), what + ": binding memory");
        void* p = nullptr;
        check(vkMapMemory(context.device, b.memory, 0, VK_WHOLE_SIZE, 0, &p), what + ": mapping");
        b.mapped = static_cast<std::byte*>(p);
    } catch (...) {
        destroyBuffer(context.device, b);
        throw;
    }
    return b;
}

void destroyBuffer(VkDevice device, const MemoryBuffer& b) {
    if (b.buffer) vkDestroyBuffer(device, b.buffer, nullptr);
    if (b.memory) vkFreeMemory(device, b.memory, nullptr);  // unmaps implicitly
}

FrameRing::FrameRing(VulkanContext& context, VulkanCounters& counters, int slots)
    : context_(context), counters_(counters), slots_(std::size_t(std::clamp(slots, 1, 4))) {
    VkDescriptorSetLayoutBinding ubo{};
    ubo.binding = 0;
    ubo.descriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC;
    ubo.descriptorCount = 1;
    ubo.stageFlags = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;
    VkDescriptorSetLayoutCreateInfo lci{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    lci.bindingCount = 1;
    lci.pBindings = &ubo;
    check(vkCreateDescriptorSetLayout(context_.device, &lci, nullptr, &uniformLayout_),
          "Vulkan backend: the uniform block's set layout");
    for (FrameSlot& s : slots_) {
        VkCommandPoolCreateInfo pci{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
        pci.flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT;
        pci.queueFamilyIndex = context_.queueFamily;
        check(vkCreateCommandPool(context_.device, &pci, nullptr, &s.pool), "Vulkan backend: a command pool");
        VkCommandBufferAllocateInfo ai{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
        ai.commandPool = s.pool;
        ai.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
        ai.commandBufferCount = 1;
        check(vkAllocateCommandBuffers(context_.device, &ai, &s.cmd), "Vulkan backend: a command buffer");
        VkFenceCreateInfo fci{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
        check(vkCreateFence(context_.device, &fci, nullptr, &s.fence), "Vulkan backend: a fence");
    }
}

FrameRing::~FrameRing() {
    drain();
    for (FrameSlot& s : slots_) {
        for (const ArenaChunk& c : s.chunks) destroyBuffer(context_.device, {c.buffer, c.memory, c.mapped});
        for (VkDescriptorPool p : s.descriptorPools) vkDestroyDescriptorPool(context_.device, p, nullptr);
        if (s.fence) vkDestroyFence(context_.device, s.fence, nullptr);
        if (s.pool) vkDestroyCommandPool(context_.device, s.pool, nullptr);
    }
    if (uniformLayout_) vkDestroyDescriptorSetLayout(context_.device, uniformLayout_, nullptr);
}

FrameSlot& FrameRing::begin() {
    FrameSlot& s = slots_[current_];
    if (s.recording) return s;
    if (s.submitted) {
        if (vkGetFenceStatus(context_.device, s.fence) != VK_SUCCESS) {
            ++counters_.fenceWaits;
            check(vkWaitForFences(context_.device, 1, &s.fence, VK_TRUE, UINT64_MAX),
                  "Vulkan backend: waiting for a frame slot");
        }
        completed_ = std::max(completed_, s.serial);
        s.submitted = false;
    }
    collect();
    reset(s);
    VkCommandBufferBeginInfo bi{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    bi.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    check(vkBeginCommandBuffer(s.cmd, &bi), "Vulkan backend: beginning a command buffer");
    s.recording = true;
    s.serial = nextSerial_;
    return s;
}

void FrameRing::reset(FrameSlot& s) {
    check(vkResetCommandPool(context_.device, s.pool, 0), "Vulkan backend: resetting a command pool");
    check(vkResetFences(context_.device, 1, &s.fence), "Vulkan backend: resetting a fence");
    s.chunk = 0;
    s.offset = 0;
    // The chunks' uniform sets live in the first pool, which is never reset: they stay valid.
    for (std::size_t i = 1; i < s.descriptorPools.size(); ++i)
        vkResetDescriptorPool(context_.device, s.descriptorPools[i], 0);
    s.descriptorPool = 1;
}

VkCommandBuffer FrameRing::cmd() { return begin().cmd; }

void FrameRing::submit(bool wait, VkSemaphore waitFor, VkPipelineStageFlags waitStage, VkSemaphore signal) {
    FrameSlot& s = slots_[current_];
    if (!s.recording) return;
    s.recording = false;
    check(vkEndCommandBuffer(s.cmd), "Vulkan backend: ending a command buffer");
    VkSubmitInfo si{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    si.commandBufferCount = 1;
    si.pCommandBuffers = &s.cmd;
    if (waitFor) {
        si.waitSemaphoreCount = 1;
        si.pWaitSemaphores = &waitFor;
        si.pWaitDstStageMask = &waitStage;
    }
    if (signal) {
        si.signalSemaphoreCount = 1;
        si.pSignalSemaphores = &signal;
    }
    check(vkQueueSubmit(context_.queue, 1, &si, s.fence), "Vulkan backend: vkQueueSubmit");
    ++counters_.submits;
    s.submitted = true;
    ++nextSerial_;
    if (wait) {
        ++counters_.resultWaits;
        check(vkWaitForFences(context_.device, 1, &s.fence, VK_TRUE, UINT64_MAX),
              "Vulkan backend: waiting for results");
        completed_ = std::max(completed_, s.serial);
        collect();
    }
    current_ = (current_ + 1) % slots_.size();
}

void FrameRing::drain() {
    if (slots_[current_].recording) submit(false);
    vkQueueWaitIdle(context_.queue);
    completed_ = nextSerial_;
    collect();
}

void FrameRing::collect() {
    std::vector<Retired> keep;
    std::vector<Retired> run;
    for (Retired& r : retired_) (r.serial <= completed_ ? run : keep).push_back(std::move(r));
    retired_ = std::move(keep);
    for (Retired& r : run) r.destroy();
}

void FrameRing::retire(std::function<void()> destroy) {
    // Whatever is recording or was submitted may use it: wait for the latest serial.
    const std::uint64_t latest = slots_[current_].recording ? nextSerial_ : nextSerial_ - 1;
    if (latest <= completed_) {
        destroy();
        return;
    }
    retired_.push_back({latest, std::move(destroy)});
}

ArenaAllocation FrameRing::allocate(std::uint64_t bytes, std::uint64_t alignment) {
    FrameSlot& s = begin();
    for (;;) {
        if (s.chunk < s.chunks.size()) {
            ArenaChunk& c = s.chunks[s.chunk];
            const std::uint64_t at = (s.offset + alignment - 1) / alignment * alignment;
            if (at + bytes <= c.size) {
                s.offset = at + bytes;
                return {c.buffer, at, c.mapped + at, c.uniformSet};
            }
            if (s.chunk + 1 < s.chunks.size() && s.chunks[s.chunk + 1].size >= bytes) {
                ++s.chunk;
                s.offset = 0;
                continue;
            }
        }
        // A new chunk, after the current one (a larger request gets a chunk of its own size).
        const std::uint64_t size = std::max(kChunkBytes, bytes);
        MemoryBuffer b = createHostBuffer(
            context_, size + kUniformWindow,
            VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
            "Vulkan backend: upload arena");
        ++counters_.buffersCreated;
        ArenaChunk c{b.buffer, b.memory, b.mapped, size, VK_NULL_HANDLE};
        if (s.descriptorPools.empty()) s.descriptorPools.push_back(newDescriptorPool());
        VkDescriptorSetAllocateInfo ai{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
        ai.descriptorPool = s.descriptorPools[0];
        ai.descriptorSetCount = 1;
        ai.pSetLayouts = &uniformLayout_;
        check(vkAllocateDescriptorSets(context_.device, &ai, &c.uniformSet), "Vulkan backend: a uniform set");
        VkDescriptorBufferInfo info{c.buffer, 0, kUniformWindow};
        VkWriteDescriptorSet w{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
        w.dstSet = c.uniformSet;
        w.dstBinding = 0;
        w.descriptorCount = 1;
        w.descriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC;
        w.pBufferInfo = &info;
        vkUpdateDescriptorSets(context_.device, 1, &w, 0, nullptr);
        const std::size_t at = s.chunk < s.chunks.size() ? s.chunk + 1 : s.chunks.size();
        s.chunks.insert(s.chunks.begin() + std::ptrdiff_t(at), c);
        s.chunk = at;
        s.offset = 0;
    }
}

VkDescriptorPool FrameRing::newDescriptorPool() {
    const VkDescriptorPoolSize sizes[] = {{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, kSetsPerPool * 4},
                                          {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC, kSetsPerPool}};
    VkDescriptorPoolCreateInfo ci{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    ci.maxSets = kSetsPerPool;
    ci.poolSizeCount = 2;
    ci.pPoolSizes = sizes;
    VkDescriptorPool pool = VK_NULL_HANDLE;
    check(vkCreateDescriptorPool(context_.device, &ci, nullptr, &pool), "Vulkan backend: a descriptor pool");
    ++counters_.descriptorPoolsCreated;
    return pool;
}

VkDescriptorSet FrameRing::allocateSet(VkDescriptorSetLayout layout) {
    FrameSlot& s = begin();
    if (s.descriptorPools.empty()) s.descriptorPools.push_back(newDescriptorPool());
    for (;;) {
        if (s.descriptorPool >= s.descriptorPools.size()) s.descriptorPools.push_back(newDescriptorPool());
        VkDescriptorSetAllocateInfo ai{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
        ai.descriptorPool = s.descriptorPools[s.descriptorPool];
        ai.descriptorSetCount = 1;
        ai.pSetLayouts = &layout;
        VkDescriptorSet set = VK_NULL_HANDLE;
        const VkResult r = vkAllocateDescriptorSets(context_.device, &ai, &set);
        if (r == VK_SUCCESS) return set;
        if (r != VK_ERROR_OUT_OF_POOL_MEMORY && r != VK_ERROR_FRAGMENTED_POOL)
            check(r, "Vulkan backend: allocating a descriptor set");
        ++s.descriptorPool;  // full: the next pool (made when there is none)
    }
}

}  // namespace engine::render::vk
