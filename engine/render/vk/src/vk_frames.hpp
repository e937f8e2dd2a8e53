// SPDX-License-Identifier: MIT
#pragma once
// The ring of frame slots. A slot is one command buffer's worth of per-submission data: the
// command buffer, its fence, an upload arena (uniform blocks, staging for texture uploads and
// readbacks) and a descriptor pool, all reused once the fence has signalled, so a steady
// frame creates none of them. Resources destroyed while a submission may still read them are
// retired here and destroyed when every submission up to that point has completed.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "engine/render/vk/vk_backend.hpp"
#include "vk_context.hpp"

namespace engine::render::vk {

// The window a draw's uniform block is bound with (its dynamic offset moves it), so the largest
// block a program may have: every chunk has this much beyond its allocatable size, so a window
// at any offset stays inside the buffer.
inline constexpr std::uint64_t kUniformWindow = 2048;

struct ArenaChunk {
    VkBuffer buffer = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    std::byte* mapped = nullptr;
    std::uint64_t size = 0;
    VkDescriptorSet uniformSet = VK_NULL_HANDLE;  // set 1: the chunk as a dynamic uniform buffer
};

struct ArenaAllocation {
    VkBuffer buffer = VK_NULL_HANDLE;
    std::uint64_t offset = 0;
    std::byte* data = nullptr;
    VkDescriptorSet uniformSet = VK_NULL_HANDLE;
};

struct FrameSlot {
    VkCommandPool pool = VK_NULL_HANDLE;
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    VkFence fence = VK_NULL_HANDLE;
    std::uint64_t serial = 0;  // of the submission recorded in it
    bool recording = false, submitted = false;
    std::vector<ArenaChunk> chunks;
    std::size_t chunk = 0;
    std::uint64_t offset = 0;
    std::vector<VkDescriptorPool> descriptorPools;  // grown while warming up, reset on reuse
    std::size_t descriptorPool = 0;
};

class FrameRing {
public:
    FrameRing(VulkanContext& context, VulkanCounters& counters, int slots);
    ~FrameRing();
    FrameRing(const FrameRing&) = delete;
    FrameRing& operator=(const FrameRing&) = delete;

    // The command buffer being recorded, begun on first use (waiting for its slot's previous
    // submission when that is still running).
    VkCommandBuffer cmd();
    bool recording() const { return slots_[current_].recording; }
    // The serial of the submission now being recorded (or next to be).
    std::uint64_t recordingSerial() const { return nextSerial_; }
    std::uint64_t completedSerial() const { return completed_; }

    // The recording slot's index (0..slots-1): per-slot objects (a swapchain's acquire
    // semaphores) are free once cmd() has begun the slot.
    std::size_t slot() const { return current_; }
    std::size_t slots() const { return slots_.size(); }

    // Ends and submits what is recorded; with `wait`, waits for it (a result wait). Moves to the
    // next slot. Nothing to submit: does nothing. `waitFor` (at `waitStage`) and `signal` are a
    // presentation's semaphores.
    void submit(bool wait, VkSemaphore waitFor = VK_NULL_HANDLE, VkPipelineStageFlags waitStage = 0,
                VkSemaphore signal = VK_NULL_HANDLE);
    // Waits until the queue has finished everything submitted (tear-down only).
    void drain();

    // `bytes` of the recording slot's arena, aligned to `alignment`.
    ArenaAllocation allocate(std::uint64_t bytes, std::uint64_t alignment);
    VkDescriptorSet allocateSet(VkDescriptorSetLayout layout);
    VkDescriptorSetLayout uniformLayout() const { return uniformLayout_; }

    // Runs `destroy` once nothing submitted so far can use what it destroys.
    void retire(std::function<void()> destroy);

private:
    FrameSlot& begin();
    void reset(FrameSlot& slot);
    void collect();
    VkDescriptorPool newDescriptorPool();

    VulkanContext& context_;
    VulkanCounters& counters_;
    std::vector<FrameSlot> slots_;
    std::size_t current_ = 0;
    std::uint64_t nextSerial_ = 1, completed_ = 0;
    VkDescriptorSetLayout uniformLayout_ = VK_NULL_HANDLE;
    struct Retired {
        std::uint64_t serial;
        std::function<void()> destroy;
    };
    std::vector<Retired> retired_;
};

// A buffer with its own memory of the given properties, mapped when host-visible. Throws
// engine::Error naming `what`; nothing is left allocated then.
struct MemoryBuffer {
    VkBuffer buffer = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    std::byte* mapped = nullptr;
};
MemoryBuffer createHostBuffer(const VulkanContext& context, std::uint64_t size, VkBufferUsageFlags usage,
                              const std::string& what);
void destroyBuffer(VkDevice device, const MemoryBuffer& buffer);

}  // namespace engine::render::vk
