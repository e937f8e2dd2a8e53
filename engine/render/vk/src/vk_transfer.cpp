// SPDX-License-Identifier: MIT
// Vulkan backend: readback (a copy into a host buffer, then the GL backend's conversion to
// floats) and resolve (the GL backend's resolve shaders: colour averaged in linear, depth the
// closest sample; a single-sampled source is copied).
#include <cstring>

#include "engine/core/error.hpp"
#include "engine/render/memory_budget.hpp"
#include "engine/render/pixel_codec.hpp"
#include "vk_backend_impl.hpp"
#include "vk_pipeline_builder.hpp"

namespace engine::render::vk {

Readback VulkanDriverImpl::readback(NativeId h, const TextureDesc&) {
    VulkanTexture& t = textures_[h];
    const FormatInfo& info = formatInfo(t.desc.format);
    const std::string what = "readback of " + quotedName(t.desc.name);
    Readback r;
    r.width = t.desc.width;
    r.height = t.desc.height;
    r.channels = info.channels;
    r.format = t.desc.format;
    const std::size_t values = std::size_t(r.width) * std::size_t(r.height) * std::size_t(r.channels);
    const std::uint64_t bytes = std::uint64_t(r.width) * std::uint64_t(r.height) * info.bytesPerPixel;
    const MemoryBuffer staging = createHostBuffer(*context_, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, what);
    ++counters_.buffersCreated;
    try {
        const VkCommandBuffer cmd = frames_->cmd();
        use(cmd, t, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT,
            false);
        VkBufferImageCopy copy{};
        copy.imageSubresource = {t.aspect, 0, 0, 1};
        copy.imageExtent = {std::uint32_t(r.width), std::uint32_t(r.height), 1};
        vkCmdCopyImageToBuffer(cmd, t.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, staging.buffer, 1, &copy);
        VkMemoryBarrier toHost{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
        toHost.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
        toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
        vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &toHost, 0, nullptr,
                             0, nullptr);
        frames_->submit(true);
        r.values.resize(values);
        // Normalized formats: the stored codes / 255 (sRGB not decoded); 16F decoded, 32F as is.
        if (info.isNormalized()) {
            const auto* codes = reinterpret_cast<const std::uint8_t*>(staging.mapped);
            for (std::size_t i = 0; i < values; ++i) r.values[i] = float(codes[i]) / 255.0f;
        } else if (info.bytesPerPixel == 2 * info.channels) {
            for (std::size_t i = 0; i < values; ++i) {
                std::uint16_t half;
                std::memcpy(&half, staging.mapped + 2 * i, 2);
                r.values[i] = decodeHalf(half);
            }
        } else {
            std::memcpy(r.values.data(), staging.mapped, values * sizeof(float));
        }
    } catch (...) {
        frames_->retire([device = context_->device, staging] { vk::destroyBuffer(device, staging); });
        throw;
    }
    vk::destroyBuffer(context_->device, staging);  // its submission has completed
    return r;
}

void VulkanDriverImpl::resolve(NativeId source, NativeId destination, const ResolveDesc& rd, const std::string&) {
    VulkanTexture& src = textures_[source];
    VulkanTexture& dst = textures_[destination];
    const bool depth = formatInfo(src.desc.format).isDepth;
    const VkCommandBuffer cmd = frames_->cmd();
    if (src.actualSamples == 1) {
        use(cmd, src, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT,
            false);
        use(cmd, dst, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_TRANSFER_BIT,
            VK_ACCESS_TRANSFER_WRITE_BIT, true);
        VkImageCopy copy{};
        copy.srcSubresource = copy.dstSubresource = {src.aspect, 0, 0, 1};
        copy.extent = {std::uint32_t(src.desc.width), std::uint32_t(src.desc.height), 1};
        vkCmdCopyImage(cmd, src.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, dst.image,
                       VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &copy);
        return;
    }
    use(cmd, src, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT,
        VK_ACCESS_SHADER_READ_BIT, false);
    RenderPassKey key;
    key.samples = 1;
    VkClearValue clear{};
    if (depth) {
        use(cmd, dst, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL,
            VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT,
            VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT, true);
        key.depth = dst.format;
    } else {
        use(cmd, dst, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
            VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT, true);
        key.color[0] = dst.format;
        key.colorCount = 1;
    }
    const VkRenderPass rp = renderPass(key);
    const VkPipeline pipeline = resolveProgramPipeline(dst.format, depth, rp);
    const VkDescriptorSet set = frames_->allocateSet(resolve_.setLayout);
    const VkDescriptorImageInfo image{sampler({Filter::Nearest, AddressMode::Clamp, AddressMode::Clamp}), src.view,
                                      VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    VkWriteDescriptorSet w{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    w.dstSet = set;
    w.descriptorCount = 1;
    w.descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    w.pImageInfo = &image;
    vkUpdateDescriptorSets(context_->device, 1, &w, 0, nullptr);
    VkRenderPassBeginInfo bi{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
    bi.renderPass = rp;
    bi.framebuffer = framebuffer(rp, {dst.view}, dst.desc.width, dst.desc.height);
    bi.renderArea = {{0, 0}, {std::uint32_t(dst.desc.width), std::uint32_t(dst.desc.height)}};
    bi.clearValueCount = 1;
    bi.pClearValues = &clear;
    vkCmdBeginRenderPass(cmd, &bi, VK_SUBPASS_CONTENTS_INLINE);
    const VkViewport viewport{0.0f, 0.0f, float(dst.desc.width), float(dst.desc.height), 0.0f, 1.0f};
    vkCmdSetViewport(cmd, 0, 1, &viewport);
    vkCmdSetScissor(cmd, 0, 1, &bi.renderArea);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, resolve_.layout, 0, 1, &set, 0, nullptr);
    const std::int32_t constants[2] = {src.actualSamples, isCloser(rd.depthFunc, 1.0f, 0.0f) ? 1 : 0};
    vkCmdPushConstants(cmd, resolve_.layout, VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof constants, constants);
    vkCmdDraw(cmd, 3, 1, 0, 0);
    vkCmdEndRenderPass(cmd);
}

VkPipeline VulkanDriverImpl::resolveProgramPipeline(VkFormat format, bool depth, VkRenderPass pass) {
    auto it = resolve_.pipelines.find(format);
    if (it != resolve_.pipelines.end()) return it->second;
    const VkDevice device = context_->device;
    auto module = [&](const std::string& source, Stage stage, VkShaderModule& out) {
        if (out) return;
        const std::vector<std::uint32_t> code = compileSpirv("resolve", stage, source);
        VkShaderModuleCreateInfo ci{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
        ci.codeSize = code.size() * 4;
        ci.pCode = code.data();
        check(vkCreateShaderModule(device, &ci, nullptr, &out), "Vulkan backend: the resolve shaders");
    };
    module(vertexSource(VertexInput::Fullscreen, "resolve", {}), Stage::Vertex, resolve_.vertex);
    module(depth ? resolveDepthSource() : resolveColorSource(), Stage::Fragment,
           depth ? resolve_.depth : resolve_.color);
    if (!resolve_.layout) {
        VkDescriptorSetLayoutBinding b{0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_FRAGMENT_BIT,
                                       nullptr};
        VkDescriptorSetLayoutCreateInfo lci{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
        lci.bindingCount = 1;
        lci.pBindings = &b;
        check(vkCreateDescriptorSetLayout(device, &lci, nullptr, &resolve_.setLayout), "Vulkan backend: resolve set");
        const VkPushConstantRange push{VK_SHADER_STAGE_FRAGMENT_BIT, 0, 8};
        VkPipelineLayoutCreateInfo pci{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
        pci.setLayoutCount = 1;
        pci.pSetLayouts = &resolve_.setLayout;
        pci.pushConstantRangeCount = 1;
        pci.pPushConstantRanges = &push;
        check(vkCreatePipelineLayout(device, &pci, nullptr, &resolve_.layout), "Vulkan backend: resolve layout");
    }
    VkPipelineColorBlendAttachmentState attachment{};
    attachment.colorWriteMask = 0xF;
    GraphicsPipelineParts parts;
    parts.vertex = resolve_.vertex;
    parts.fragment = depth ? resolve_.depth : resolve_.color;
    parts.depthTest = depth;  // ALWAYS: every pixel written (GL: GL_ALWAYS, mask on)
    parts.depthWrite = depth;
    if (!depth) parts.blends = {&attachment, 1};
    parts.layout = resolve_.layout;
    parts.renderPass = pass;
    VkPipeline p = createGraphicsPipeline(device, parts, "Vulkan backend: a resolve pipeline");
    ++counters_.pipelinesCreated;
    resolve_.pipelines.emplace(format, p);
    return p;
}

void VulkanDriverImpl::destroyResolvePipelines() {
    const VkDevice device = context_->device;
    for (const auto& [format, p] : resolve_.pipelines) vkDestroyPipeline(device, p, nullptr);
    if (resolve_.layout) vkDestroyPipelineLayout(device, resolve_.layout, nullptr);
    if (resolve_.setLayout) vkDestroyDescriptorSetLayout(device, resolve_.setLayout, nullptr);
    for (VkShaderModule m : {resolve_.vertex, resolve_.color, resolve_.depth})
        if (m) vkDestroyShaderModule(device, m, nullptr);
}

}  // namespace engine::render::vk
