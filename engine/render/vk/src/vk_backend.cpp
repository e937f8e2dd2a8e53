// SPDX-License-Identifier: MIT
// Vulkan driver: creation (device, frame ring, the identity instance), tear-down and the frame
// boundary.
#include <cstring>

#include "engine/core/error.hpp"
#include "engine/core/log.hpp"
#include "vk_backend_impl.hpp"

namespace engine::render::vk {

VulkanProgram::~VulkanProgram() {
    for (const auto& [key, p] : pipelines) vkDestroyPipeline(device, p, nullptr);
    if (layout) vkDestroyPipelineLayout(device, layout, nullptr);
    if (textureLayout) vkDestroyDescriptorSetLayout(device, textureLayout, nullptr);
    if (vertex) vkDestroyShaderModule(device, vertex, nullptr);
    for (VkShaderModule f : fragments)
        if (f) vkDestroyShaderModule(device, f, nullptr);
}

VulkanDriverImpl::VulkanDriverImpl(const VulkanOptions& options, std::unique_ptr<VulkanContext> context)
    : options_(options), context_(std::move(context)) {
    frames_ = std::make_unique<FrameRing>(*context_, counters_, options_.framesInFlight);
    if (options_.window) swapchain_ = std::make_unique<Swapchain>(*context_, counters_, frames_->slots());
    const Instance identity{};
    identityInstance_ = createHostBuffer(*context_, sizeof identity, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT,
                                         "Vulkan backend: the identity instance");
    std::memcpy(identityInstance_.mapped, &identity, sizeof identity);
    ++counters_.buffersCreated;
    VkQueryPoolCreateInfo qci{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
    qci.queryType = VK_QUERY_TYPE_OCCLUSION;
    qci.queryCount = kOcclusionSlots;
    check(vkCreateQueryPool(context_->device, &qci, nullptr, &occlusion_), "Vulkan backend: the occlusion queries");
    qci.queryType = VK_QUERY_TYPE_TIMESTAMP;
    qci.queryCount = kTimestampSlots;
    check(vkCreateQueryPool(context_->device, &qci, nullptr, &timestamps_), "Vulkan backend: the pass timestamps");
    log::debug("Vulkan backend: ", context_->info.device, " (", context_->info.driver, ")");
}

VulkanDriverImpl::~VulkanDriverImpl() {
    pass_.reset();
    draws_.clear();
    frames_->drain();
    swapchain_.reset();
    const VkDevice device = context_->device;
    programs_ = {};
    destroyResolvePipelines();
    for (const auto& [key, fb] : framebuffers_) vkDestroyFramebuffer(device, fb, nullptr);
    for (const auto& [key, rp] : renderPasses_) vkDestroyRenderPass(device, rp, nullptr);
    for (const auto& [key, s] : samplers_) vkDestroySampler(device, s, nullptr);
    // Textures and buffers still alive: the pools hold them; destroy what they own.
    textures_.forEach([&](const VulkanTexture& t) { destroyTextureObjects(t); });
    buffers_.forEach([&](const VulkanBuffer& b) { vk::destroyBuffer(device, {b.buffer, b.memory, b.mapped}); });
    for (const auto& [key, spare] : spareBuffers_) vk::destroyBuffer(device, spare);
    vk::destroyBuffer(device, identityInstance_);
    if (occlusion_) vkDestroyQueryPool(device, occlusion_, nullptr);
    if (timestamps_) vkDestroyQueryPool(device, timestamps_, nullptr);
    frames_.reset();
}

void VulkanDriverImpl::endFrame() { frames_->submit(false); }

std::unique_ptr<Device> createVulkanBackend(const VulkanOptions& options) {
    return std::make_unique<Device>(std::make_unique<VulkanDriverImpl>(options, VulkanContext::create(options)));
}

std::string vulkanUnavailableReason(const VulkanOptions& options) {
    try {
        VulkanContext::create(options);
        return {};
    } catch (const Error& e) {
        return e.what();
    }
}

}  // namespace engine::render::vk
