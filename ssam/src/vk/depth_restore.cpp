// SPDX-License-Identifier: MIT
// Settings::depthMaskThreshold in ssam::vk, as ssam::gl does it (ssam/src/gl/depth_restore.hpp):
// the colour pass writes the foliage depth wherever a leaf passes the alpha test ([Hathaway 2010]
// §3.7), also where the composite then shows mostly what is behind the leaf, so a later
// transparent pass is cut there (a rim of the unblended background round the leaves). With a
// threshold the host's opaque depth is copied before the colour pass and written back after the
// composite wherever the composited mask is below it: one depth copy and one full-screen
// depth-only pass (restore.frag: core/glsl/composite*.glsl and depth_restore_main.glsl), both over
// the composite's region.
#include "impl.hpp"

namespace ssam::vk {

namespace {

VkImageAspectFlags aspectsOf(VkFormat depth) {
    const bool stencil = depth == VK_FORMAT_D24_UNORM_S8_UINT || depth == VK_FORMAT_D32_SFLOAT_S8_UINT;
    return VK_IMAGE_ASPECT_DEPTH_BIT | (stencil ? VK_IMAGE_ASPECT_STENCIL_BIT : 0);
}

VkImageMemoryBarrier imageBarrier(VkImage image, VkImageAspectFlags aspects, VkImageLayout from, VkImageLayout to,
                                  VkAccessFlags srcAccess, VkAccessFlags dstAccess) {
    VkImageMemoryBarrier b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
    b.srcAccessMask = srcAccess;
    b.dstAccessMask = dstAccess;
    b.oldLayout = from;
    b.newLayout = to;
    b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    b.image = image;
    b.subresourceRange = {aspects, 0, 1, 0, 1};  // a layout change covers every aspect of the image
    return b;
}

constexpr VkPipelineStageFlags kDepthTests =
    VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT;

}  // namespace

// Between the mask and the colour pass, outside any render pass: the host's depth goes to
// TRANSFER_SRC_OPTIMAL and back (SSAM's own barriers), its depth aspect copied into SSAM's image
// over the region; the previous frame's restore read of that image (FRAGMENT_SHADER) comes first.
void ScreenSpaceAlphaMaskVk::Impl::saveOpaqueDepth(const detail::Generation& g) {
    const VkCommandBuffer cb = frame.commandBuffer;
    const VkImageAspectFlags aspects = aspectsOf(frame.depthFormat);
    const VkImageMemoryBarrier in[2] = {
        imageBarrier(frame.depthImage, aspects, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL,
                     VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
                     VK_ACCESS_TRANSFER_READ_BIT),
        imageBarrier(g.savedDepth.image, aspects, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 0,
                     VK_ACCESS_TRANSFER_WRITE_BIT)};
    vk.CmdPipelineBarrier(cb, kDepthTests | VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0,
                          nullptr, 0, nullptr, 2, in);
    VkImageCopy copy{};
    copy.srcSubresource = copy.dstSubresource = {VK_IMAGE_ASPECT_DEPTH_BIT, 0, 0, 1};  // the stencil stays
    copy.srcOffset = copy.dstOffset = {region.x, region.y, 0};
    copy.extent = {std::uint32_t(region.width), std::uint32_t(region.height), 1};
    vk.CmdCopyImage(cb, frame.depthImage, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, g.savedDepth.image,
                    VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &copy);
    const VkImageMemoryBarrier out[2] = {
        imageBarrier(frame.depthImage, aspects, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                     VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL, 0,
                     VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT),
        imageBarrier(g.savedDepth.image, aspects, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                     VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_ACCESS_TRANSFER_WRITE_BIT,
                     VK_ACCESS_SHADER_READ_BIT)};
    vk.CmdPipelineBarrier(cb, VK_PIPELINE_STAGE_TRANSFER_BIT, kDepthTests | VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, 0, 0,
                          nullptr, 0, nullptr, 2, out);
}

// After the composite: a depth-only pass over the host's depth (compare ALWAYS, write on),
// scissored to the region, writing the saved depth where the composited mask is below the
// threshold (elsewhere the shader discards and the foliage depth stays).
void ScreenSpaceAlphaMaskVk::Impl::restoreDepth(const detail::Generation& g, const detail::CompositePush& push) {
    const VkCommandBuffer cb = frame.commandBuffer;
    beginPass(frame, g, &framebuffers, detail::PassKind::DepthRestore, nullptr, g.restorePipeline);
    const VkRect2D scissor{{region.x, region.y}, {std::uint32_t(region.width), std::uint32_t(region.height)}};
    vk.CmdSetScissor(cb, 0, 1, &scissor);
    vk.CmdBindDescriptorSets(cb, VK_PIPELINE_BIND_POINT_GRAPHICS, shared.restoreLayout, 0, 1, &g.restoreSet, 0,
                             nullptr);
    vk.CmdPushConstants(cb, shared.restoreLayout, VK_SHADER_STAGE_FRAGMENT_BIT, 0, detail::kRestorePushSize, &push);
    vk.CmdDraw(cb, 3, 1, 0, 0);
    endPass(cb, g, detail::PassKind::DepthRestore);
}

}  // namespace ssam::vk
