// SPDX-License-Identifier: MIT
#include "dynamic_rendering.hpp"

namespace ssam::vk::detail {

namespace {

// The render-pass path's external dependencies, both ways: attachment writes (colour, depth) and,
// for the intermediates' reuse, the composite's sampled reads (a write after read needs only the
// stage).
constexpr VkPipelineStageFlags kStages =
    VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT | VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT |
    VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT;
constexpr VkAccessFlags kWrites = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
constexpr VkAccessFlags kAccesses = kWrites | VK_ACCESS_COLOR_ATTACHMENT_READ_BIT |
                                    VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_SHADER_READ_BIT;

bool hasStencil(VkFormat f) { return f == VK_FORMAT_D24_UNORM_S8_UINT || f == VK_FORMAT_D32_SFLOAT_S8_UINT; }

// The intermediates a pass draws into: none (composite, depth restore), rt_foliage, the mask (and
// Rg16f's ADD mask).
struct Intermediates {
    VkImage images[2] = {VK_NULL_HANDLE, VK_NULL_HANDLE};
    std::uint32_t count = 0;
};

Intermediates intermediates(const Generation& g, PassKind pass) {
    Intermediates out;
    if (pass == PassKind::Mask) {
        out.images[out.count++] = g.mask.image;
        if (g.maskAdd.image) out.images[out.count++] = g.maskAdd.image;
    } else if (pass == PassKind::Color) {
        out.images[out.count++] = g.foliage.image;
    }
    return out;
}

// A memory barrier of the contract's stages and accesses, with the intermediates' layout transitions.
void barrier(const VkFunctions& vk, VkCommandBuffer cb, const Intermediates& images, VkImageLayout from,
             VkImageLayout to) {
    VkMemoryBarrier memory{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    memory.srcAccessMask = kWrites;
    memory.dstAccessMask = kAccesses;
    VkImageMemoryBarrier layouts[2];
    for (std::uint32_t i = 0; i < images.count; ++i) {
        VkImageMemoryBarrier& layout = layouts[i];
        layout = {VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
        layout.srcAccessMask = kWrites;
        layout.dstAccessMask = kAccesses;
        layout.oldLayout = from;
        layout.newLayout = to;
        layout.srcQueueFamilyIndex = layout.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        layout.image = images.images[i];
        layout.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    }
    vk.CmdPipelineBarrier(cb, kStages, kStages, 0, 1, &memory, 0, nullptr, images.count, layouts);
}

}  // namespace

void beginDynamicPass(const VkFunctions& vk, VkCommandBuffer cb, PassKind pass, const Generation& g,
                      const DynamicPassTargets& t, const VkClearValue* clear) {
    const bool composite = pass == PassKind::Composite;
    // The render-pass path's initialLayout UNDEFINED (cleared anyway) and its dependency in.
    // (The composite and the depth restore follow a pass whose barrier out covers them.)
    if (pass == PassKind::Mask || pass == PassKind::Color)
        barrier(vk, cb, intermediates(g, pass), VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
    VkRenderingAttachmentInfo colors[2] = {{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO},
                                           {VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO}};
    colors[0].imageView = composite ? t.hostColor : pass == PassKind::Mask ? g.mask.view : g.foliage.view;
    colors[1].imageView = g.maskAdd.view;  // Rg16f's mask pass only
    for (VkRenderingAttachmentInfo& color : colors) {
        color.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
        color.loadOp = composite ? VK_ATTACHMENT_LOAD_OP_LOAD : VK_ATTACHMENT_LOAD_OP_CLEAR;
        color.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
        if (clear) color.clearValue = *clear;
    }
    VkRenderingAttachmentInfo depth{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    depth.imageView = t.hostDepth;
    depth.imageLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
    depth.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;
    depth.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    VkRenderingInfo info{VK_STRUCTURE_TYPE_RENDERING_INFO};
    info.renderArea = {{0, 0}, {t.width, t.height}};
    info.layerCount = 1;
    info.colorAttachmentCount = pass == PassKind::DepthRestore ? 0 : pass == PassKind::Mask && g.maskAdd.image ? 2 : 1;
    info.pColorAttachments = colors;
    if (!composite) {
        info.pDepthAttachment = &depth;
        if (hasStencil(t.depthFormat)) info.pStencilAttachment = &depth;  // kept as the host left it
    }
    vk.CmdBeginRendering(cb, &info);
}

void endDynamicPass(const VkFunctions& vk, VkCommandBuffer cb, PassKind pass, const Generation& g) {
    vk.CmdEndRendering(cb);
    // The render-pass path's finalLayout (sampled by the composite) and its dependency out.
    if (pass == PassKind::Composite || pass == PassKind::DepthRestore)
        barrier(vk, cb, {}, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_UNDEFINED);
    else
        barrier(vk, cb, intermediates(g, pass), VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
}

}  // namespace ssam::vk::detail
