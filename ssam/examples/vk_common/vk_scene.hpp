// SPDX-License-Identifier: MIT
#pragma once
// The Vulkan examples' host scene (the GL examples' scene.hpp, on the device): its render targets,
// the cards' vertex buffer, the leaf texture, its opaque pass, the readback of an image.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <vector>

#include <vulkan/vulkan.h>

#include <ssam/vk/ssam_vk.hpp>

#include "scene.hpp"
#include "vk_host.hpp"

namespace vk_example {

using namespace gl_example;  // the scene

// World (x, y up, z in [0, 1]) to Vulkan's clip space (y down, z in [0, w]), column-major.
constexpr float kViewProj[16] = {1, 0, 0, 0, 0, -1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

constexpr std::uint32_t kCardVertices = kCardRows * 6;

// The pixels a rasterised axis-aligned quad covers (centres inside [a, b)): the host's opaque
// quads are flat, so it clears them with vkCmdClearAttachments instead of a pipeline of its own.
inline VkClearRect clearRect(const Rect3& r) {
    const auto first = [](float edge) { return std::max(0, static_cast<int>(std::ceil(edge - 0.5f))); };
    const float left = (r.x0 * 0.5f + 0.5f) * kWidth, right = (r.x1 * 0.5f + 0.5f) * kWidth;
    const float top = (0.5f - r.y1 * 0.5f) * kHeight, bottom = (0.5f - r.y0 * 0.5f) * kHeight;
    const int x0 = first(left), x1 = std::min(kWidth, first(right)), y0 = first(top),
              y1 = std::min(kHeight, first(bottom));
    return {{{x0, y0}, {std::uint32_t(x1 - x0), std::uint32_t(y1 - y0)}}, 0, 1};
}

// The host's scene on the device: its render targets, the cards' vertex buffer, the leaf texture,
// its opaque render pass.
struct HostScene {
    vk_example::VulkanHost& host;
    vk_example::HostImage color, depth, leaf;
    vk_example::HostBuffer vertices, readback;
    std::vector<ssam::vk::Box> cardBounds;  // FrameDesc::foliageBounds
    VkRenderPass opaquePass = VK_NULL_HANDLE;
    VkFramebuffer framebuffer = VK_NULL_HANDLE;

    // `wind`: how far (world units, in x) the host's shaders bend the cards' tops; 0 for none.
    HostScene(vk_example::VulkanHost& h, float wind) : host(h) {
        color = host.createImage(VK_FORMAT_R8G8B8A8_UNORM, kWidth, kHeight,
                                 VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                                 VK_IMAGE_ASPECT_COLOR_BIT);
        // TRANSFER_SRC: Settings::depthMaskThreshold has SSAM copy the opaque depth.
        depth = host.createImage(VK_FORMAT_D32_SFLOAT, kWidth, kHeight,
                                 VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                                 VK_IMAGE_ASPECT_DEPTH_BIT);
        leaf =
            host.createImage(VK_FORMAT_R8G8B8A8_UNORM, kLeafSize, kLeafSize,
                             VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT, VK_IMAGE_ASPECT_COLOR_BIT);
        std::vector<Vertex> cards;
        for (const Rect3& r : kCards) {
            appendStrip(cards, r, kCardRows);
            // Bounds hold every pixel the card can reach, bent or not (or the composite's scissor
            // would cut the bend off): the wind moves its top |wind| at most, in x.
            cardBounds.push_back({{r.x0 + std::min(wind, 0.0f), r.y0, std::min(r.zLeft, r.zRight)},
                                  {r.x1 + std::max(wind, 0.0f), r.y1, std::max(r.zLeft, r.zRight)}});
        }
        vertices = host.createBuffer(cards.size() * sizeof(Vertex), VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
        std::memcpy(vertices.mapped, cards.data(), cards.size() * sizeof(Vertex));
        readback = host.createBuffer(VkDeviceSize(kWidth) * kHeight * 4,
                                     VK_BUFFER_USAGE_TRANSFER_DST_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
        createOpaquePass();
        uploadLeaf();
    }
    ~HostScene() {
        vkDestroyFramebuffer(host.device, framebuffer, nullptr);
        vkDestroyRenderPass(host.device, opaquePass, nullptr);
        for (auto* i : {&color, &depth, &leaf}) host.destroy(*i);
        for (auto* b : {&vertices, &readback}) host.destroy(*b);
    }
    HostScene(const HostScene&) = delete;
    HostScene& operator=(const HostScene&) = delete;

    // A render pass over the colour and depth, left in the layouts ssam::vk expects (its contract):
    // colour COLOR_ATTACHMENT_OPTIMAL, depth DEPTH_STENCIL_ATTACHMENT_OPTIMAL, written by
    // attachment stages. `clear`: both cleared (the opaque pass; in: whatever the previous frame's
    // SSAM passes and readback did to them), else loaded from those layouts (a later pass).
    VkRenderPass createPass(bool clear, const char* what) const {
        VkAttachmentDescription a[2]{};
        a[0].format = color.format;
        a[1].format = depth.format;
        for (auto& d : a) {
            d.samples = VK_SAMPLE_COUNT_1_BIT;
            d.loadOp = clear ? VK_ATTACHMENT_LOAD_OP_CLEAR : VK_ATTACHMENT_LOAD_OP_LOAD;
            d.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
            d.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
            d.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
        }
        a[0].finalLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
        a[1].finalLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
        a[0].initialLayout = clear ? VK_IMAGE_LAYOUT_UNDEFINED : a[0].finalLayout;
        a[1].initialLayout = clear ? VK_IMAGE_LAYOUT_UNDEFINED : a[1].finalLayout;
        const VkAttachmentReference colorRef{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
        const VkAttachmentReference depthRef{1, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
        VkSubpassDescription subpass{};
        subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
        subpass.colorAttachmentCount = 1;
        subpass.pColorAttachments = &colorRef;
        subpass.pDepthStencilAttachment = &depthRef;
        constexpr VkPipelineStageFlags kAttachments = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT |
                                                      VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT |
                                                      VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT;
        constexpr VkAccessFlags kWrites =
            VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
        constexpr VkAccessFlags kAccesses =
            kWrites | VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT;
        // In: the clearing pass also follows the previous frame's readback (a transfer).
        const VkPipelineStageFlags before = clear ? kAttachments | VK_PIPELINE_STAGE_TRANSFER_BIT : kAttachments;
        const VkSubpassDependency dependencies[2] = {
            {VK_SUBPASS_EXTERNAL, 0, before, kAttachments, kWrites, kAccesses, 0},
            // Out: the contract's entry row of ssam::vk (attachment writes at attachment stages).
            {0, VK_SUBPASS_EXTERNAL, kAttachments, kAttachments, kWrites, kAccesses, 0}};
        VkRenderPassCreateInfo info{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
        info.attachmentCount = 2;
        info.pAttachments = a;
        info.subpassCount = 1;
        info.pSubpasses = &subpass;
        info.dependencyCount = 2;
        info.pDependencies = dependencies;
        VkRenderPass pass = VK_NULL_HANDLE;
        check(vkCreateRenderPass(host.device, &info, nullptr, &pass), what);
        return pass;
    }
    // The colour and depth as `pass`'s attachments.
    VkFramebuffer createFramebuffer(VkRenderPass pass, const char* what) const {
        const VkImageView views[2] = {color.view, depth.view};
        VkFramebufferCreateInfo fb{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
        fb.renderPass = pass;
        fb.attachmentCount = 2;
        fb.pAttachments = views;
        fb.width = kWidth;
        fb.height = kHeight;
        fb.layers = 1;
        VkFramebuffer framebuffer = VK_NULL_HANDLE;
        check(vkCreateFramebuffer(host.device, &fb, nullptr, &framebuffer), what);
        return framebuffer;
    }
    // Cleared to the sky and depth 1 (recordOpaque).
    void createOpaquePass() {
        opaquePass = createPass(true, "vkCreateRenderPass");
        framebuffer = createFramebuffer(opaquePass, "vkCreateFramebuffer");
    }

    void uploadLeaf() {
        vk_example::HostBuffer staging = host.createBuffer(kLeafSize * kLeafSize * 4, VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
        auto* bytes = static_cast<std::uint8_t*>(staging.mapped);
        for (int y = 0; y < kLeafSize; ++y)
            for (int x = 0; x < kLeafSize; ++x) std::memcpy(bytes + (y * kLeafSize + x) * 4, leafTexel(x, y).data(), 4);
        const VkCommandBuffer cb = host.begin();
        imageBarrier(cb, leaf.image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                     VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, 0,
                     VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT);
        VkBufferImageCopy region{};
        region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        region.imageExtent = {kLeafSize, kLeafSize, 1};
        vkCmdCopyBufferToImage(cb, staging.buffer, leaf.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
        // Ready for SSAM's fragment-shader reads (createTexture's contract).
        imageBarrier(cb, leaf.image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                     VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_TRANSFER_BIT,
                     VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, VK_ACCESS_SHADER_READ_BIT);
        host.wait(host.submit(cb));
        host.destroy(staging);
    }

    void recordOpaque(VkCommandBuffer cb) const {
        VkClearValue clears[2]{};
        clears[0].color = {{kSky[0], kSky[1], kSky[2], 1.0f}};
        clears[1].depthStencil = {1.0f, 0};
        VkRenderPassBeginInfo begin{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
        begin.renderPass = opaquePass;
        begin.framebuffer = framebuffer;
        begin.renderArea = {{0, 0}, {kWidth, kHeight}};
        begin.clearValueCount = 2;
        begin.pClearValues = clears;
        vkCmdBeginRenderPass(cb, &begin, VK_SUBPASS_CONTENTS_INLINE);
        for (const Rect3& r : {kGround, kBox, kBoxTop}) {
            VkClearAttachment attachments[2]{};
            attachments[0].aspectMask = VK_IMAGE_ASPECT_COLOR_BIT;
            attachments[0].clearValue.color = {{r.color[0], r.color[1], r.color[2], r.color[3]}};
            attachments[1].aspectMask = VK_IMAGE_ASPECT_DEPTH_BIT;
            attachments[1].clearValue.depthStencil = {r.zLeft, 0};
            const VkClearRect rect = clearRect(r);
            vkCmdClearAttachments(cb, 2, attachments, 1, &rect);
        }
        vkCmdEndRenderPass(cb);
    }

    // The cards from the host's own vertex buffer (position at 0, uv at 12): binds it, then for each
    // card calls setTint(tint rgb, alpha factor) and draws it; the same cards in the same order
    // every time (§3.8).
    void drawCards(VkCommandBuffer cb, const std::function<void(const float tint[4])>& setTint) const {
        const VkDeviceSize offset = 0;
        vkCmdBindVertexBuffers(cb, 0, 1, &vertices.buffer, &offset);
        for (std::size_t i = 0; i < kCards.size(); ++i) {
            setTint(kCards[i].color.data());
            vkCmdDraw(cb, kCardVertices, 1, std::uint32_t(i) * kCardVertices, 0);
        }
    }

    // Copies `image` (in `layout`, last written at COLOR_ATTACHMENT_OUTPUT, maybe read by SSAM's
    // composite) into the readback buffer and returns its RGBA8 rows, top first.
    std::vector<std::uint8_t> read(VkImage image, VkImageLayout layout) {
        const VkCommandBuffer cb = host.begin();
        imageBarrier(cb, image, VK_IMAGE_ASPECT_COLOR_BIT, layout, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                     VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT | VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT,
                     VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT);
        VkBufferImageCopy region{};
        region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        region.imageExtent = {kWidth, kHeight, 1};
        vkCmdCopyImageToBuffer(cb, image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback.buffer, 1, &region);
        imageBarrier(cb, image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, layout,
                     VK_PIPELINE_STAGE_TRANSFER_BIT, 0, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT, 0);
        host.wait(host.submit(cb));
        const auto* bytes = static_cast<const std::uint8_t*>(readback.mapped);
        return {bytes, bytes + std::size_t(kWidth) * kHeight * 4};
    }
};

}  // namespace vk_example
