// SPDX-License-Identifier: MIT
// Vulkan backend: render pass objects, framebuffers, samplers and pipelines. A pipeline is made
// from the front end's resolved state (resolved_draw_state.hpp) and one fail-mode step, for the
// pass's formats, the first time a draw needs it, and cached in its program by all of that.
#include <algorithm>
#include <array>
#include <cstring>

#include "engine/core/error.hpp"
#include "vk_backend_impl.hpp"
#include "vk_pipeline_builder.hpp"

namespace engine::render::vk {
namespace {

// Vulkan "Blend Factors"; SRC_ALPHA_SATURATE is (f, f, f, 1) with f = min(As, 1 - Ad) as
// BlendFactor::SrcAlphaSat, and Vulkan accepts it as a destination factor too.
VkBlendFactor vkBlendFactor(BlendFactor f) {
    switch (f) {
        case BlendFactor::Zero: return VK_BLEND_FACTOR_ZERO;
        case BlendFactor::One: return VK_BLEND_FACTOR_ONE;
        case BlendFactor::SrcColor: return VK_BLEND_FACTOR_SRC_COLOR;
        case BlendFactor::InvSrcColor: return VK_BLEND_FACTOR_ONE_MINUS_SRC_COLOR;
        case BlendFactor::SrcAlpha: return VK_BLEND_FACTOR_SRC_ALPHA;
        case BlendFactor::InvSrcAlpha: return VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
        case BlendFactor::DstColor: return VK_BLEND_FACTOR_DST_COLOR;
        case BlendFactor::InvDstColor: return VK_BLEND_FACTOR_ONE_MINUS_DST_COLOR;
        case BlendFactor::DstAlpha: return VK_BLEND_FACTOR_DST_ALPHA;
        case BlendFactor::InvDstAlpha: return VK_BLEND_FACTOR_ONE_MINUS_DST_ALPHA;
        case BlendFactor::SrcAlphaSat: return VK_BLEND_FACTOR_SRC_ALPHA_SATURATE;
        case BlendFactor::ConstantColor: return VK_BLEND_FACTOR_CONSTANT_COLOR;
        case BlendFactor::InvConstantColor: return VK_BLEND_FACTOR_ONE_MINUS_CONSTANT_COLOR;
        case BlendFactor::ConstantAlpha: return VK_BLEND_FACTOR_CONSTANT_ALPHA;
        case BlendFactor::InvConstantAlpha: return VK_BLEND_FACTOR_ONE_MINUS_CONSTANT_ALPHA;
    }
    return VK_BLEND_FACTOR_ONE;
}

VkBlendOp vkBlendOp(BlendOp op) {
    switch (op) {
        case BlendOp::Add: return VK_BLEND_OP_ADD;
        case BlendOp::Subtract: return VK_BLEND_OP_SUBTRACT;
        case BlendOp::RevSubtract: return VK_BLEND_OP_REVERSE_SUBTRACT;
        case BlendOp::Min: return VK_BLEND_OP_MIN;
        case BlendOp::Max: return VK_BLEND_OP_MAX;
    }
    return VK_BLEND_OP_ADD;
}

// CompareFunc is in the order of VkCompareOp (and GL's).
VkCompareOp vkCompare(CompareFunc f) { return VkCompareOp(int(f)); }
static_assert(VK_COMPARE_OP_NEVER == 0 && VK_COMPARE_OP_LESS == 1 && VK_COMPARE_OP_ALWAYS == 7);

VkSamplerAddressMode vkAddress(AddressMode m) {
    switch (m) {
        case AddressMode::Wrap: return VK_SAMPLER_ADDRESS_MODE_REPEAT;
        case AddressMode::Clamp: return VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
        case AddressMode::Mirror: return VK_SAMPLER_ADDRESS_MODE_MIRRORED_REPEAT;
    }
    return VK_SAMPLER_ADDRESS_MODE_REPEAT;
}

// The pipeline's key: everything that makes it, as plain bytes (no padding to compare).
class KeyWriter {
public:
    template <typename T>
    KeyWriter& operator<<(T value) {
        const auto* p = reinterpret_cast<const std::uint8_t*>(&value);
        bytes.insert(bytes.end(), p, p + sizeof value);
        return *this;
    }
    std::vector<std::uint8_t> bytes;
};

}  // namespace

VkRenderPass VulkanDriverImpl::renderPass(const RenderPassKey& key) {
    auto it = renderPasses_.find(key);
    if (it != renderPasses_.end()) return it->second;
    // Attachments stay in their attachment layouts: the backend's own barriers put them there
    // before the pass (it tracks each image's layout), so the pass makes no transition.
    std::vector<VkAttachmentDescription> attachments;
    std::vector<VkAttachmentReference> colors;
    for (int i = 0; i < key.colorCount; ++i) {
        VkAttachmentDescription a{};
        a.format = key.color[std::size_t(i)];
        a.samples = VkSampleCountFlagBits(key.samples);
        a.loadOp = key.load[std::size_t(i)] ? VK_ATTACHMENT_LOAD_OP_LOAD : VK_ATTACHMENT_LOAD_OP_CLEAR;
        a.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
        a.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
        a.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
        a.initialLayout = a.finalLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
        attachments.push_back(a);
        colors.push_back({std::uint32_t(i), VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL});
    }
    VkAttachmentReference depth{};
    if (key.depth != VK_FORMAT_UNDEFINED) {
        VkAttachmentDescription a{};
        a.format = key.depth;
        a.samples = VkSampleCountFlagBits(key.samples);
        a.loadOp = key.depthLoad ? VK_ATTACHMENT_LOAD_OP_LOAD : VK_ATTACHMENT_LOAD_OP_CLEAR;
        a.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
        a.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
        a.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
        a.initialLayout = a.finalLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
        depth = {std::uint32_t(attachments.size()), VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
        attachments.push_back(a);
    }
    VkSubpassDescription subpass{};
    subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
    subpass.colorAttachmentCount = std::uint32_t(colors.size());
    subpass.pColorAttachments = colors.data();
    subpass.pDepthStencilAttachment = key.depth != VK_FORMAT_UNDEFINED ? &depth : nullptr;
    VkRenderPassCreateInfo ci{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
    ci.attachmentCount = std::uint32_t(attachments.size());
    ci.pAttachments = attachments.data();
    ci.subpassCount = 1;
    ci.pSubpasses = &subpass;
    VkRenderPass pass = VK_NULL_HANDLE;
    check(vkCreateRenderPass(context_->device, &ci, nullptr, &pass), "Vulkan backend: a render pass");
    renderPasses_.emplace(key, pass);
    return pass;
}

VkFramebuffer VulkanDriverImpl::framebuffer(VkRenderPass pass, const std::vector<VkImageView>& views, int width,
                                            int height) {
    FramebufferKey key{pass, views, width, height};
    auto it = framebuffers_.find(key);
    if (it != framebuffers_.end()) return it->second;
    VkFramebufferCreateInfo ci{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
    ci.renderPass = pass;
    ci.attachmentCount = std::uint32_t(views.size());
    ci.pAttachments = views.data();
    ci.width = std::uint32_t(width);
    ci.height = std::uint32_t(height);
    ci.layers = 1;
    VkFramebuffer fb = VK_NULL_HANDLE;
    check(vkCreateFramebuffer(context_->device, &ci, nullptr, &fb), "Vulkan backend: a framebuffer");
    framebuffers_.emplace(std::move(key), fb);
    return fb;
}

void VulkanDriverImpl::forgetFramebuffers(VkImageView view) {
    for (auto it = framebuffers_.begin(); it != framebuffers_.end();) {
        if (std::find(it->first.views.begin(), it->first.views.end(), view) != it->first.views.end()) {
            frames_->retire(
                [device = context_->device, fb = it->second] { vkDestroyFramebuffer(device, fb, nullptr); });
            it = framebuffers_.erase(it);
        } else {
            ++it;
        }
    }
}

// As the GL backend's samplers (gl_caches.cpp): nearest and bilinear read the base level only,
// trilinear's LOD is the program's own (glsl/lit_surface.hpp), which reads levels with textureLod.
VkSampler VulkanDriverImpl::sampler(const SamplerState& s) {
    const int index = int(s.filter) * 9 + int(s.addressU) * 3 + int(s.addressV);
    auto it = samplers_.find(index);
    if (it != samplers_.end()) return it->second;
    VkSamplerCreateInfo ci{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    ci.magFilter = s.filter == Filter::Nearest ? VK_FILTER_NEAREST : VK_FILTER_LINEAR;
    ci.minFilter = ci.magFilter;
    // Linear between levels only for trilinear (which reads levels itself with textureLod):
    // formats without linear filtering (R32F, D32F) are read with the nearest samplers.
    ci.mipmapMode = s.filter == Filter::Trilinear ? VK_SAMPLER_MIPMAP_MODE_LINEAR : VK_SAMPLER_MIPMAP_MODE_NEAREST;
    ci.addressModeU = vkAddress(s.addressU);
    ci.addressModeV = vkAddress(s.addressV);
    ci.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    ci.minLod = 0.0f;
    ci.maxLod = s.filter == Filter::Trilinear ? VK_LOD_CLAMP_NONE : 0.0f;
    VkSampler sampler = VK_NULL_HANDLE;
    check(vkCreateSampler(context_->device, &ci, nullptr, &sampler), "Vulkan backend: a sampler");
    samplers_.emplace(index, sampler);
    return sampler;
}

VkPipeline VulkanDriverImpl::pipeline(const VulkanProgram& program, const PipelineDesc& desc,
                                      const ResolvedDrawState& state, const PlanStep& step, const RenderPassKey& pass) {
    const bool fullscreen = program.desc->vertexInput == VertexInput::Fullscreen;
    // Compatibility does not depend on load operations: the pipeline is made against the
    // pass with every attachment cleared, and runs in any pass with these formats and samples.
    RenderPassKey compatible = pass;
    compatible.load = {};
    compatible.depthLoad = 0;
    const std::uint8_t cull = fullscreen ? 0 : std::uint8_t(desc.raster.cull);
    std::array<std::uint8_t, kMaxColorTargets> masks{};
    KeyWriter key;
    key << compatible.colorCount << compatible.samples << compatible.depth << std::uint8_t(state.depthTest)
        << std::uint8_t(step.depthWrite) << state.depthFunc << cull << desc.raster.frontFace;
    for (int i = 0; i < state.colorTargetCount; ++i) {
        const BlendState& b = state.blend[std::size_t(i)];
        masks[std::size_t(i)] = std::uint8_t(b.writeMask & step.channels);
        key << compatible.color[std::size_t(i)] << std::uint8_t(state.blendNeeded[std::size_t(i)]) << b.srcRgb
            << b.dstRgb << b.opRgb << b.srcAlpha << b.dstAlpha << b.opAlpha << masks[std::size_t(i)];
    }
    std::vector<std::uint8_t> bytes = std::move(key.bytes);
    auto it = program.pipelines.find(bytes);
    if (it != program.pipelines.end()) return it->second;

    // The engine's one vertex layout (vertex.hpp): Vertex per vertex, Instance per instance.
    const VkVertexInputBindingDescription bindings[] = {{0, sizeof(Vertex), VK_VERTEX_INPUT_RATE_VERTEX},
                                                        {1, sizeof(Instance), VK_VERTEX_INPUT_RATE_INSTANCE}};
    const VkVertexInputAttributeDescription attributes[] = {
        {0, 0, VK_FORMAT_R32G32B32_SFLOAT, std::uint32_t(offsetof(Vertex, position))},
        {1, 0, VK_FORMAT_R32G32B32_SFLOAT, std::uint32_t(offsetof(Vertex, normal))},
        {2, 0, VK_FORMAT_R32G32_SFLOAT, std::uint32_t(offsetof(Vertex, uv))},
        {3, 0, VK_FORMAT_R32G32B32A32_SFLOAT, std::uint32_t(offsetof(Vertex, color))},
        {4, 1, VK_FORMAT_R32G32B32A32_SFLOAT, std::uint32_t(offsetof(Instance, model))},
        {5, 1, VK_FORMAT_R32G32B32A32_SFLOAT, std::uint32_t(offsetof(Instance, model) + 16)},
        {6, 1, VK_FORMAT_R32G32B32A32_SFLOAT, std::uint32_t(offsetof(Instance, model) + 32)},
        {7, 1, VK_FORMAT_R32G32B32A32_SFLOAT, std::uint32_t(offsetof(Instance, model) + 48)},
        {8, 1, VK_FORMAT_R32G32B32A32_SFLOAT, std::uint32_t(offsetof(Instance, tint))}};
    std::vector<VkPipelineColorBlendAttachmentState> blends;
    for (int i = 0; i < state.colorTargetCount; ++i) {
        const BlendState& b = state.blend[std::size_t(i)];
        VkPipelineColorBlendAttachmentState a{};
        a.blendEnable = state.blendNeeded[std::size_t(i)];
        a.srcColorBlendFactor = vkBlendFactor(b.srcRgb);
        a.dstColorBlendFactor = vkBlendFactor(b.dstRgb);
        a.colorBlendOp = vkBlendOp(b.opRgb);
        a.srcAlphaBlendFactor = vkBlendFactor(b.srcAlpha);
        a.dstAlphaBlendFactor = vkBlendFactor(b.dstAlpha);
        a.alphaBlendOp = vkBlendOp(b.opAlpha);
        const std::uint8_t m = masks[std::size_t(i)];
        a.colorWriteMask =
            ((m & WriteR) ? VK_COLOR_COMPONENT_R_BIT : 0) | ((m & WriteG) ? VK_COLOR_COMPONENT_G_BIT : 0) |
            ((m & WriteB) ? VK_COLOR_COMPONENT_B_BIT : 0) | ((m & WriteA) ? VK_COLOR_COMPONENT_A_BIT : 0);
        blends.push_back(a);
    }
    GraphicsPipelineParts parts;
    parts.vertex = program.vertex;
    parts.fragment = fragmentModule(program, state.colorTargetCount);
    if (!fullscreen) {
        parts.bindings = bindings;
        parts.attributes = attributes;
    }
    parts.cull = cull == std::uint8_t(CullMode::Back)    ? VK_CULL_MODE_BACK_BIT
                 : cull == std::uint8_t(CullMode::Front) ? VK_CULL_MODE_FRONT_BIT
                                                         : VK_CULL_MODE_NONE;
    // Facing as displayed: Vulkan decides it in framebuffer space, where the negative-height
    // viewport has put row 0 at the top, so counter-clockwise as displayed is Vulkan's
    // counter-clockwise (RasterConformance.CullingAndFrontFace).
    parts.frontFace =
        desc.raster.frontFace == Winding::CounterClockwise ? VK_FRONT_FACE_COUNTER_CLOCKWISE : VK_FRONT_FACE_CLOCKWISE;
    parts.samples = VkSampleCountFlagBits(pass.samples);
    parts.depthTest = state.depthTest;
    parts.depthWrite = state.depthTest && step.depthWrite;
    parts.depthCompare = vkCompare(state.depthFunc);
    parts.blends = blends;
    parts.dynamicBlendConstants = true;
    parts.layout = program.layout;
    parts.renderPass = renderPass(compatible);
    VkPipeline p = createGraphicsPipeline(context_->device, parts,
                                          "pipeline " + quotedName(desc.name) + ": vkCreateGraphicsPipelines");
    ++counters_.pipelinesCreated;
    program.pipelines.emplace(std::move(bytes), p);
    return p;
}

}  // namespace engine::render::vk
