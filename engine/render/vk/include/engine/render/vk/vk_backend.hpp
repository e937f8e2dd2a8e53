// SPDX-License-Identifier: MIT
#pragma once
// The Vulkan 1.3 driver under the render front end (device.hpp): the same semantics as the
// soft driver (the reference) and the GL driver, on an explicit API. Headless on any Vulkan 1.3 device (Mesa's lavapipe on CI).
//
// Conventions (so images match the soft backend without flips): a negative-height viewport
// (Vulkan 1.1 core) maps NDC +y to framebuffer row 0, the first stored row and the top of a
// Readback, as the GL backend's glClipControl(GL_UPPER_LEFT, GL_ZERO_TO_ONE) does; depth is
// z/w in [0, 1] natively. Vulkan decides facing in framebuffer space, where row 0 is then at the
// top: counter-clockwise as displayed is Vulkan's counter-clockwise, as on GL.
//
// Explicit done right: draws are recorded until endPass, so the barriers for what they sample
// precede the render pass; every image's layout and last access are tracked here, not by a
// frame graph; per-submission data (uniform blocks, uploads, descriptor sets) lives in a ring
// of frame slots, each reused once its fence has signalled.
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "engine/render/device.hpp"
#include "engine/render/driver.hpp"
#include "engine/render/memory_budget.hpp"

namespace engine::render::vk {

class VulkanWindow;  // vk_window.hpp

enum class FailModeStrategy : std::uint8_t {
    TwoPass,      // passing fragments, then failing ones: fast, inexact where one draw overlaps itself
    PerTriangle,  // the same two steps per triangle: exact, two draws per triangle
};

struct VulkanOptions {
    // -1: the first device with Vulkan 1.3 and a graphics queue; >= 0: that device (the error
    // lists the devices when it does not exist).
    int device = -1;
    // VK_LAYER_KHRONOS_validation with synchronization validation and a debug messenger. Every
    // warning or error it reports is counted (validationMessages()) and passed to onValidation
    // (default: logged as a warning). Tests turn it on and fail on any message.
    bool validation = false;
    std::function<void(const std::string& message)> onValidation;
    FailModeStrategy failModes = FailModeStrategy::TwoPass;
    int framesInFlight = 2;  // frame slots in the ring (1..4)
    // A window to present to (present()): its surface's instance extensions and
    // VK_KHR_swapchain are enabled, and the device's graphics queue must present to it.
    std::shared_ptr<VulkanWindow> window;
    // What the device can still allocate, asked before each image and buffer is allocated
    // (memory_budget.hpp: refused by name unless twice its size is free). Empty: the host's
    // memory on a CPU device (lavapipe keeps images in host memory, as llvmpipe GL does), else
    // the device-local heap's size less what this backend holds. Tests set a small one.
    MemoryProbe memory;
};

struct VulkanInfo {
    std::string device;  // "llvmpipe (LLVM 15.0.6, 256 bits)"
    std::string driver;  // driver name and info
    std::uint32_t apiVersion = 0;
    int deviceIndex = 0;
    bool validation = false;
};

// What a frame did, for the steady-frame checks: counted since the backend was made.
struct VulkanCounters {
    std::uint64_t pipelinesCreated = 0;
    std::uint64_t imagesCreated = 0;
    std::uint64_t buffersCreated = 0;  // VkBuffers, the ring's own chunks included
    std::uint64_t descriptorPoolsCreated = 0;
    std::uint64_t fenceWaits = 0;   // waits for a frame slot to come free
    std::uint64_t resultWaits = 0;  // waits for readback or query results
    std::uint64_t submits = 0;
    std::uint64_t swapchainsCreated = 0;  // the first, then one per recreation (resize, out of date)
    std::uint64_t framesPresented = 0;
};

// What only the Vulkan driver offers, reached as device.driverAs<VulkanDriver>().
// Device::present shows a colour texture (scaled to the window's size when it differs) in
// VulkanOptions::window through a FIFO swapchain, and submits what is recorded (so call it
// after endFrame or instead of it). False when nothing was shown: the window is minimised
// (its framebuffer is empty), or the swapchain was out of date and is made anew for the next
// frame. Throws engine::Error without a window. endFrame() submits what is recorded and moves
// to the next frame slot; the next use of a slot waits only when its previous submission is
// still running.
class VulkanDriver : public Driver {
public:
    virtual const VulkanInfo& info() const = 0;
    virtual const VulkanCounters& counters() const = 0;
    // Validation warnings and errors reported since the driver was made.
    virtual std::uint64_t validationMessages() const = 0;
};

// A render device over the Vulkan driver. Throws engine::Error when there is no Vulkan loader,
// no Vulkan 1.3 device, no device `device` (the message lists them) or, with validation, no
// validation layer.
std::unique_ptr<Device> createVulkanBackend(const VulkanOptions& options = {});

// The Vulkan driver under `device`; engine::Error when it runs another.
inline VulkanDriver& vulkanDriver(const Device& device) { return device.driverAs<VulkanDriver>(); }

// Empty when a backend with these options can be made here, else why not (for test skips).
std::string vulkanUnavailableReason(const VulkanOptions& options = {});

}  // namespace engine::render::vk
