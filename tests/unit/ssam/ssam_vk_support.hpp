// SPDX-License-Identifier: MIT
#pragma once
// What the ssam::vk tests share: SSAM's device description of the examples' Vulkan host, its
// error messages, and host render targets of one size that a test clears, hands to SSAM and
// reads back, each left as ssam::vk's synchronization contract asks (ssam_vk.hpp).
#include <cstdint>
#include <cstring>
#include <deque>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <ssam/vk/ssam_vk.hpp>

#include "ssam_device.hpp"
#include "vk_host.hpp"

namespace ssam_vk_test {

struct Messages {
    std::vector<std::string> errors;
    static void record(void* user, ssam::vk::Severity severity, const char* message) {
        if (severity == ssam::vk::Severity::Error) static_cast<Messages*>(user)->errors.push_back(message);
    }
};

inline ssam::vk::DeviceDesc describe(const vk_example::VulkanHost& host) { return vk_example::ssamDevice(host); }

using vk_example::imageBarrier;

inline constexpr VkPipelineStageFlags kAttachmentStages = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT |
                                                          VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT |
                                                          VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT;

// Host render targets of one size: R8G8B8A8_UNORM colour and D32_SFLOAT depth, with TRANSFER
// usage so that a test can clear them and read them back.
struct Targets {
    vk_example::VulkanHost& host;
    std::uint32_t width, height;
    vk_example::HostImage color, depth;
    vk_example::HostBuffer readback;  // the colour's RGBA8 rows, then the depth's floats
    Targets(vk_example::VulkanHost& h, std::uint32_t w, std::uint32_t hgt) : host(h), width(w), height(hgt) {
        constexpr VkImageUsageFlags transfer = VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
        color = host.createImage(VK_FORMAT_R8G8B8A8_UNORM, w, hgt, VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | transfer,
                                 VK_IMAGE_ASPECT_COLOR_BIT);
        depth = host.createImage(VK_FORMAT_D32_SFLOAT, w, hgt, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | transfer,
                                 VK_IMAGE_ASPECT_DEPTH_BIT);
        readback = host.createBuffer(VkDeviceSize(w) * hgt * 8, VK_BUFFER_USAGE_TRANSFER_DST_BIT);
    }
    ~Targets() {
        host.destroy(color);
        host.destroy(depth);
        host.destroy(readback);
    }
    Targets(const Targets&) = delete;
    Targets& operator=(const Targets&) = delete;

    // A frame of SSAM's over these targets, recorded into `cb`.
    ssam::vk::FrameDesc frame(VkCommandBuffer cb) const {
        ssam::vk::FrameDesc f;
        f.commandBuffer = cb;
        f.colorView = color.view;
        f.colorFormat = color.format;
        f.colorImageExtent = {width, height};
        f.depthView = depth.view;
        f.depthFormat = depth.format;
        f.depthImageExtent = {width, height};
        f.width = width;
        f.height = height;
        return f;
    }
    // prepare(), then frame(): a frame over targets in the contract's entry layouts.
    ssam::vk::FrameDesc preparedFrame(VkCommandBuffer cb) const {
        prepare(cb);
        return frame(cb);
    }
    // Into the contract's entry layouts (attachment writes: an image barrier of attachment stages).
    void prepare(VkCommandBuffer cb) const {
        imageBarrier(cb, color.image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                     VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, kAttachmentStages, 0, kAttachmentStages,
                     VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_COLOR_ATTACHMENT_READ_BIT);
        imageBarrier(cb, depth.image, VK_IMAGE_ASPECT_DEPTH_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                     VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL, kAttachmentStages, 0, kAttachmentStages,
                     VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT);
    }
    // Both images made transfer destinations (their contents discarded).
    void toTransferDestination(VkCommandBuffer cb) const {
        imageBarrier(cb, color.image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                     VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, 0,
                     VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT);
        imageBarrier(cb, depth.image, VK_IMAGE_ASPECT_DEPTH_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                     VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, 0,
                     VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT);
    }
    // From the transfers that wrote them into the contract's entry layouts (the host's barrier from
    // its transfer into the attachment stages: the contract's "another stage" case).
    void toEntryLayouts(VkCommandBuffer cb) const {
        imageBarrier(cb, color.image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                     VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_TRANSFER_BIT,
                     VK_ACCESS_TRANSFER_WRITE_BIT, kAttachmentStages,
                     VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_COLOR_ATTACHMENT_READ_BIT);
        imageBarrier(cb, depth.image, VK_IMAGE_ASPECT_DEPTH_BIT, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                     VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_TRANSFER_BIT,
                     VK_ACCESS_TRANSFER_WRITE_BIT, kAttachmentStages,
                     VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT);
    }
    // Cleared by transfers, then handed over in the contract's entry layouts (the host's barrier
    // from its transfer into the attachment stages: the contract's "another stage" case).
    void clear(VkCommandBuffer cb, const float rgba[4], float z) const {
        toTransferDestination(cb);
        VkClearColorValue c;
        std::memcpy(c.float32, rgba, sizeof c.float32);
        const VkImageSubresourceRange colorRange{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
        const VkImageSubresourceRange depthRange{VK_IMAGE_ASPECT_DEPTH_BIT, 0, 1, 0, 1};
        vkCmdClearColorImage(cb, color.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &c, 1, &colorRange);
        const VkClearDepthStencilValue d{z, 0};
        vkCmdClearDepthStencilImage(cb, depth.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &d, 1, &depthRange);
        toEntryLayouts(cb);
    }
    // Filled from `source` (the colour's RGBA8 rows, then the depth's floats: readback's layout) by
    // transfers, then handed over in the contract's entry layouts, as clear() does.
    void upload(VkCommandBuffer cb, const vk_example::HostBuffer& source) const {
        toTransferDestination(cb);
        VkBufferImageCopy region{};
        region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        region.imageExtent = {width, height, 1};
        vkCmdCopyBufferToImage(cb, source.buffer, color.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
        region.bufferOffset = VkDeviceSize(width) * height * 4;
        region.imageSubresource.aspectMask = VK_IMAGE_ASPECT_DEPTH_BIT;
        vkCmdCopyBufferToImage(cb, source.buffer, depth.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
        toEntryLayouts(cb);
    }
    // Copies both images (in the contract's exit layouts) into `readback`, host-readable once the
    // command buffer completed; they are left in TRANSFER_SRC_OPTIMAL.
    void copyOut(VkCommandBuffer cb) const {
        imageBarrier(cb, color.image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                     VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, kAttachmentStages, VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT,
                     VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT);
        imageBarrier(cb, depth.image, VK_IMAGE_ASPECT_DEPTH_BIT, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL,
                     VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, kAttachmentStages,
                     VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
                     VK_ACCESS_TRANSFER_READ_BIT);
        VkBufferImageCopy region{};
        region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        region.imageExtent = {width, height, 1};
        vkCmdCopyImageToBuffer(cb, color.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback.buffer, 1, &region);
        region.bufferOffset = VkDeviceSize(width) * height * 4;
        region.imageSubresource.aspectMask = VK_IMAGE_ASPECT_DEPTH_BIT;
        vkCmdCopyImageToBuffer(cb, depth.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback.buffer, 1, &region);
        VkBufferMemoryBarrier toHost{VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER};
        toHost.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
        toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
        toHost.srcQueueFamilyIndex = toHost.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        toHost.buffer = readback.buffer;
        toHost.size = VK_WHOLE_SIZE;
        vkCmdPipelineBarrier(cb, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 0, nullptr, 1, &toHost,
                             0, nullptr);
    }
    // After copyOut()'s command buffer completed.
    const std::uint8_t* rgba(std::uint32_t x, std::uint32_t y) const {
        return static_cast<const std::uint8_t*>(readback.mapped) + (std::size_t(y) * width + x) * 4;
    }
    float z(std::uint32_t x, std::uint32_t y) const {
        float value;
        std::memcpy(&value,
                    static_cast<const std::uint8_t*>(readback.mapped) + std::size_t(width) * height * 4 +
                        (std::size_t(y) * width + x) * 4,
                    sizeof value);
        return value;
    }
};

// What most tests start from: new targets of one size, a command buffer being recorded and
// SSAM's frame over both (`prepared`: the targets put into the contract's entry layouts first).
struct HostFrame {
    Targets targets;
    VkCommandBuffer cb;
    ssam::vk::FrameDesc frame;
    HostFrame(vk_example::VulkanHost& host, std::uint32_t width, std::uint32_t height, bool prepared = true)
        : targets(host, width, height), cb(host.begin()) {
        frame = prepared ? targets.preparedFrame(cb) : targets.frame(cb);
    }
    // Submitted under validation: whatever SSAM refused, the command buffer must still be valid.
    void submitAndWait() const { targets.host.wait(targets.host.submit(cb)); }
};

// Frames recorded the way a host's ring of two frame slots records them: before a third is
// recorded the oldest is waited for, and each frame says how many have completed
// (FrameDesc::framesCompleted).
struct FramesInFlight {
    vk_example::VulkanHost& host;
    std::deque<VkFence> fences;
    std::uint64_t completed = 0;

    // SSAM's render() of `targets`' prepared frame number `frame`, drawing nothing, then submitted.
    ssam::vk::Status renderNothing(ssam::vk::ScreenSpaceAlphaMaskVk& ssam, const Targets& targets,
                                   std::uint64_t frame) {
        if (fences.size() == 2) {
            host.wait(fences.front());
            fences.pop_front();
            ++completed;
        }
        const VkCommandBuffer cb = host.begin();
        ssam::vk::FrameDesc f = targets.preparedFrame(cb);
        f.frameIndex = frame;
        f.framesCompleted = completed;
        const ssam::vk::Status status = ssam.render(f, [](const ssam::vk::FoliageProgram&) {});
        fences.push_back(host.submit(cb));
        return status;
    }
    void waitForAll() {
        for (VkFence f : fences) host.wait(f);
        completed += fences.size();
        fences.clear();
    }
};

// A quad over the middle half of the frame at depth 0.5, drawn by SSAM's built-in programs (the
// default VertexLayout: positions only, binding 0) in `rgb`, opaque: the composite
// shows exactly that colour there (mask 1, squared 1).
struct CentreQuad {
    vk_example::VulkanHost& host;
    vk_example::HostBuffer vertices;
    explicit CentreQuad(vk_example::VulkanHost& h) : host(h) {
        const float v[18] = {-0.5f, -0.5f, 0.5f, 0.5f, -0.5f, 0.5f, 0.5f,  0.5f, 0.5f,
                             -0.5f, -0.5f, 0.5f, 0.5f, 0.5f,  0.5f, -0.5f, 0.5f, 0.5f};
        vertices = host.createBuffer(sizeof v, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
        std::memcpy(vertices.mapped, v, sizeof v);
    }
    ~CentreQuad() { host.destroy(vertices); }
    CentreQuad(const CentreQuad&) = delete;
    CentreQuad& operator=(const CentreQuad&) = delete;
    void draw(const ssam::vk::FoliageProgram& p, const float rgb[3]) const {
        const VkDeviceSize offset = 0;
        vkCmdBindVertexBuffers(p.commandBuffer, 0, 1, &vertices.buffer, &offset);
        p.setBaseColorFactor(rgb[0], rgb[1], rgb[2], 1.0f);
        vkCmdDraw(p.commandBuffer, 6, 1, 0, 0);
    }
};

}  // namespace ssam_vk_test
