// SPDX-License-Identifier: MIT
#include "pipelines.hpp"

#include <algorithm>
#include <array>
#include <string>

#include "failure.hpp"
#include "ssam_vk_spirv.hpp"  // generated: glslc's output of glsl_variants.cpp's sources

namespace ssam::vk::detail {

namespace {

VkShaderModule createModule(const VkFunctions& vk, const std::uint32_t* code, std::size_t bytes, const char* what) {
    VkShaderModuleCreateInfo info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
    info.codeSize = bytes;
    info.pCode = code;
    VkShaderModule module = VK_NULL_HANDLE;
    check(vk.CreateShaderModule(vk.device, &info, vk.allocator, &module),
          (std::string("vkCreateShaderModule, ") + what).c_str());
    return module;
}

VkDescriptorSetLayout createSetLayout(const VkFunctions& vk, VkDescriptorType type, std::uint32_t count,
                                      VkShaderStageFlags stages) {
    std::array<VkDescriptorSetLayoutBinding, 3> bindings{};
    for (std::uint32_t i = 0; i < count; ++i) bindings[i] = {i, type, 1, stages, nullptr};
    VkDescriptorSetLayoutCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    info.bindingCount = count;
    info.pBindings = bindings.data();
    VkDescriptorSetLayout layout = VK_NULL_HANDLE;
    check(vk.CreateDescriptorSetLayout(vk.device, &info, vk.allocator, &layout), "vkCreateDescriptorSetLayout");
    return layout;
}

VkSampler createSampler(const VkFunctions& vk, VkFilter filter) {
    VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    info.magFilter = info.minFilter = filter;
    info.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
    info.addressModeU = info.addressModeV = info.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    info.maxLod = 0.0f;
    VkSampler sampler = VK_NULL_HANDLE;
    check(vk.CreateSampler(vk.device, &info, vk.allocator, &sampler), "vkCreateSampler");
    return sampler;
}

bool hasStencil(VkFormat f) { return f == VK_FORMAT_D24_UNORM_S8_UINT || f == VK_FORMAT_D32_SFLOAT_S8_UINT; }

// One subpass: a colour target (cleared, or loaded for the composite) and optionally the host's
// depth (loaded and stored, stencil too). The external dependencies are the synchronization
// contract (ssam_vk.hpp): in, the host's or SSAM's previous attachment writes and SSAM's previous
// sampled reads of its intermediates (WAR); out, these attachment writes for the next pass's
// attachment use or sampling, and for the host's.
VkRenderPass createRenderPass(const VkFunctions& vk, VkFormat color, bool clearColor, VkImageLayout colorFinal,
                              VkFormat depth) {
    std::array<VkAttachmentDescription, 2> attachments{};
    attachments[0].format = color;
    attachments[0].samples = VK_SAMPLE_COUNT_1_BIT;
    attachments[0].loadOp = clearColor ? VK_ATTACHMENT_LOAD_OP_CLEAR : VK_ATTACHMENT_LOAD_OP_LOAD;
    attachments[0].storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    attachments[0].stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    attachments[0].stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    attachments[0].initialLayout = clearColor ? VK_IMAGE_LAYOUT_UNDEFINED : VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    attachments[0].finalLayout = colorFinal;
    attachments[1].format = depth;
    attachments[1].samples = VK_SAMPLE_COUNT_1_BIT;
    attachments[1].loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;
    attachments[1].storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    attachments[1].stencilLoadOp = hasStencil(depth) ? VK_ATTACHMENT_LOAD_OP_LOAD : VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    attachments[1].stencilStoreOp = hasStencil(depth) ? VK_ATTACHMENT_STORE_OP_STORE : VK_ATTACHMENT_STORE_OP_DONT_CARE;
    attachments[1].initialLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
    attachments[1].finalLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
    const VkAttachmentReference colorRef{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
    const VkAttachmentReference depthRef{1, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
    VkSubpassDescription subpass{};
    subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
    subpass.colorAttachmentCount = 1;
    subpass.pColorAttachments = &colorRef;
    if (depth != VK_FORMAT_UNDEFINED) subpass.pDepthStencilAttachment = &depthRef;
    constexpr VkPipelineStageFlags kStages =
        VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT | VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT |
        VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT;
    constexpr VkAccessFlags kWrites =
        VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
    constexpr VkAccessFlags kAccesses = kWrites | VK_ACCESS_COLOR_ATTACHMENT_READ_BIT |
                                        VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_SHADER_READ_BIT;
    const std::array<VkSubpassDependency, 2> dependencies{{
        {VK_SUBPASS_EXTERNAL, 0, kStages, kStages, kWrites, kAccesses, 0},
        {0, VK_SUBPASS_EXTERNAL, kStages, kStages, kWrites, kAccesses, 0},
    }};
    VkRenderPassCreateInfo info{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
    info.attachmentCount = depth != VK_FORMAT_UNDEFINED ? 2 : 1;
    info.pAttachments = attachments.data();
    info.subpassCount = 1;
    info.pSubpasses = &subpass;
    info.dependencyCount = 2;
    info.pDependencies = dependencies.data();
    VkRenderPass pass = VK_NULL_HANDLE;
    check(vk.CreateRenderPass(vk.device, &info, vk.allocator, &pass), "vkCreateRenderPass");
    return pass;
}

VkCompareOp toVk(DepthTest test) {
    switch (test) {
        case DepthTest::Less: return VK_COMPARE_OP_LESS;
        case DepthTest::LessEqual: return VK_COMPARE_OP_LESS_OR_EQUAL;
        case DepthTest::Greater: return VK_COMPARE_OP_GREATER;
        case DepthTest::GreaterEqual: return VK_COMPARE_OP_GREATER_OR_EQUAL;
    }
    return VK_COMPARE_OP_LESS;
}

// Where the shaders' locations 0-7 (foliage.vert) come from: the host's bindings, or SSAM's
// constants buffer (offsets: ssam_vk.cpp's Constants) for an attribute the host does not give.
struct VertexInput {
    std::vector<VkVertexInputBindingDescription> bindings;
    std::vector<VkVertexInputAttributeDescription> attributes;
};
// The mask pass reads no normal (mask.vert): no attribute at location 1 there, which validation
// would report as not consumed.
VertexInput vertexInput(const VertexLayout& layout, bool withNormal) {
    VertexInput in;
    for (std::uint32_t i = 0; i < layout.bindingCount; ++i)
        in.bindings.push_back({layout.bindings[i].binding, layout.bindings[i].stride, layout.bindings[i].inputRate});
    // Stride 0: every vertex reads the same constant.
    in.bindings.push_back({layout.constantsBinding, 0, VK_VERTEX_INPUT_RATE_VERTEX});
    const auto add = [&](std::uint32_t location, const VertexAttribute& a, VkFormat constantFormat,
                         std::uint32_t constantOffset) {
        if (a.format != VK_FORMAT_UNDEFINED) in.attributes.push_back({location, a.binding, a.format, a.offset});
        else in.attributes.push_back({location, layout.constantsBinding, constantFormat, constantOffset});
    };
    constexpr std::uint32_t base = 256;  // Constants::vertex in ssam_vk.cpp
    add(0, layout.position, VK_FORMAT_R32G32B32_SFLOAT, base);
    if (withNormal) add(1, layout.normal, VK_FORMAT_R32G32B32_SFLOAT, base);
    add(2, layout.uv, VK_FORMAT_R32G32_SFLOAT, base + 16);
    add(3, layout.color, VK_FORMAT_R32G32B32A32_SFLOAT, base + 32);
    for (std::uint32_t c = 0; c < 4; ++c) {
        VertexAttribute column = layout.instanceModel;
        column.offset += 16 * c;
        if (column.format != VK_FORMAT_UNDEFINED) column.format = VK_FORMAT_R32G32B32A32_SFLOAT;
        add(4 + c, column, VK_FORMAT_R32G32B32A32_SFLOAT, base + 48 + 16 * c);
    }
    return in;
}

using Kind = PassKind;

// With `pass` null (RenderingPath::DynamicRendering) the attachment formats come from
// VkPipelineRenderingCreateInfo instead.
VkPipeline createPipeline(const VkFunctions& vk, const SharedObjects& shared, Kind kind, VkRenderPass pass,
                          VkFormat colorFormat, VkFormat depthFormat, const Settings& settings) {
    const bool composite = kind == Kind::Composite;
    VkPipelineShaderStageCreateInfo stages[2]{{VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO},
                                              {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO}};
    stages[0].stage = VK_SHADER_STAGE_VERTEX_BIT;
    stages[0].module = composite            ? shared.fullscreenVertex
                       : kind == Kind::Mask ? shared.maskVertex
                                            : shared.foliageVertex;
    stages[0].pName = "main";
    stages[1].stage = VK_SHADER_STAGE_FRAGMENT_BIT;
    stages[1].module = composite            ? shared.compositeFragment
                       : kind == Kind::Mask ? shared.maskFragment
                                            : shared.colorFragment;
    stages[1].pName = "main";
    const VertexInput input = composite ? VertexInput{} : vertexInput(settings.vertexLayout, kind == Kind::Color);
    VkPipelineVertexInputStateCreateInfo vertex{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
    vertex.vertexBindingDescriptionCount = std::uint32_t(input.bindings.size());
    vertex.pVertexBindingDescriptions = input.bindings.data();
    vertex.vertexAttributeDescriptionCount = std::uint32_t(input.attributes.size());
    vertex.pVertexAttributeDescriptions = input.attributes.data();
    VkPipelineInputAssemblyStateCreateInfo assembly{VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
    assembly.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
    VkPipelineViewportStateCreateInfo viewport{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
    viewport.viewportCount = viewport.scissorCount = 1;
    PipelineState state;
    fixedState(kind, settings, state);
    VkPipelineColorBlendStateCreateInfo blending{VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
    blending.attachmentCount = 1;
    blending.pAttachments = &state.blendAttachment;
    const VkDynamicState dynamics[] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
    VkPipelineDynamicStateCreateInfo dynamic{VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO};
    dynamic.dynamicStateCount = 2;
    dynamic.pDynamicStates = dynamics;
    VkGraphicsPipelineCreateInfo info{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO};
    info.stageCount = 2;
    info.pStages = stages;
    info.pVertexInputState = &vertex;
    info.pInputAssemblyState = &assembly;
    info.pViewportState = &viewport;
    info.pRasterizationState = &state.rasterization;
    info.pMultisampleState = &state.multisample;
    info.pDepthStencilState = composite ? nullptr : &state.depthStencil;
    info.pColorBlendState = &blending;
    info.pDynamicState = &dynamic;
    info.layout = composite ? shared.compositeLayout : shared.foliageLayout;
    info.renderPass = pass;
    VkPipelineRenderingCreateInfo rendering{VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO};
    rendering.colorAttachmentCount = 1;
    rendering.pColorAttachmentFormats = &colorFormat;
    rendering.depthAttachmentFormat = depthFormat;
    rendering.stencilAttachmentFormat = hasStencil(depthFormat) ? depthFormat : VK_FORMAT_UNDEFINED;
    if (!pass) info.pNext = &rendering;
    VkPipeline pipeline = VK_NULL_HANDLE;
    check(vk.CreateGraphicsPipelines(vk.device, VK_NULL_HANDLE, 1, &info, vk.allocator, &pipeline),
          kind == Kind::Mask ? "vkCreateGraphicsPipelines, mask" : "vkCreateGraphicsPipelines");
    return pipeline;
}

VkFramebuffer createFramebuffer(const VkFunctions& vk, VkRenderPass pass, std::initializer_list<VkImageView> views,
                                std::uint32_t width, std::uint32_t height) {
    VkFramebufferCreateInfo info{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
    info.renderPass = pass;
    info.attachmentCount = std::uint32_t(views.size());
    info.pAttachments = views.begin();
    info.width = width;
    info.height = height;
    info.layers = 1;
    VkFramebuffer framebuffer = VK_NULL_HANDLE;
    check(vk.CreateFramebuffer(vk.device, &info, vk.allocator, &framebuffer), "vkCreateFramebuffer");
    return framebuffer;
}

void destroyFramebuffers(const VkFunctions& vk, const FrameFramebuffers& f) noexcept {
    for (VkFramebuffer fb : {f.mask, f.color, f.composite})
        if (fb) vk.DestroyFramebuffer(vk.device, fb, vk.allocator);
}

constexpr std::size_t kFramebufferCacheSize = 8;  // e.g. a swapchain's images, each with its depth

}  // namespace

void fixedState(PassKind kind, const Settings& settings, PipelineState& state) {
    // Both faces: a foliage card is seen from both sides (§3.5.2-3).
    state.rasterization = {VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
    state.rasterization.polygonMode = VK_POLYGON_MODE_FILL;
    state.rasterization.cullMode = VK_CULL_MODE_NONE;
    state.rasterization.frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
    state.rasterization.lineWidth = 1.0f;
    state.multisample = {VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
    state.multisample.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
    // Mask: tested, not written; colour: tested and written (§3.7); composite: none.
    state.depthStencil = {VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
    state.depthStencil.depthTestEnable = kind == Kind::Composite ? VK_FALSE : VK_TRUE;
    state.depthStencil.depthWriteEnable = kind == Kind::Color ? VK_TRUE : VK_FALSE;
    state.depthStencil.depthCompareOp = toVk(settings.depthTest);
    VkPipelineColorBlendAttachmentState& blend = state.blendAttachment;
    blend = {};
    blend.colorWriteMask =
        VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT | VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT;
    if (kind == Kind::Mask) {  // Table 3.1: RGB = MAX, A = ADD, all ONE
        blend.blendEnable = VK_TRUE;
        blend.srcColorBlendFactor = blend.dstColorBlendFactor = VK_BLEND_FACTOR_ONE;
        blend.srcAlphaBlendFactor = blend.dstAlphaBlendFactor = VK_BLEND_FACTOR_ONE;
        blend.colorBlendOp = VK_BLEND_OP_MAX;
        blend.alphaBlendOp = VK_BLEND_OP_ADD;
    } else if (kind == Kind::Composite) {  // Listing 3.2: lerp(opaque, foliage, mask'), the host's alpha kept
        blend.blendEnable = VK_TRUE;
        blend.srcColorBlendFactor = VK_BLEND_FACTOR_SRC_ALPHA;
        blend.dstColorBlendFactor = VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
        blend.colorBlendOp = VK_BLEND_OP_ADD;
        blend.srcAlphaBlendFactor = VK_BLEND_FACTOR_ZERO;
        blend.dstAlphaBlendFactor = VK_BLEND_FACTOR_ONE;
        blend.alphaBlendOp = VK_BLEND_OP_ADD;
    }
}

VkRenderPass createPassFor(const VkFunctions& vk, PassKind pass, VkFormat target, VkFormat depth) {
    if (pass == Kind::Composite)
        return createRenderPass(vk, target, false, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_FORMAT_UNDEFINED);
    return createRenderPass(vk, target, true, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, depth);
}

void SharedObjects::create(const VkFunctions& vk) {
    try {
        foliageVertex = createModule(vk, spirv::kFoliageVert, spirv::kFoliageVertSize, "foliage.vert");
        maskVertex = createModule(vk, spirv::kMaskVert, spirv::kMaskVertSize, "mask.vert");
        maskFragment = createModule(vk, spirv::kMaskFrag, spirv::kMaskFragSize, "mask.frag");
        colorFragment = createModule(vk, spirv::kColorFrag, spirv::kColorFragSize, "color.frag");
        fullscreenVertex = createModule(vk, spirv::kFullscreenVert, spirv::kFullscreenVertSize, "fullscreen.vert");
        compositeFragment = createModule(vk, spirv::kCompositeFrag, spirv::kCompositeFragSize, "composite.frag");
        frameSetLayout = createSetLayout(vk, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1,
                                         VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT);
        textureSetLayout =
            createSetLayout(vk, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_FRAGMENT_BIT);
        compositeSetLayout =
            createSetLayout(vk, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 3, VK_SHADER_STAGE_FRAGMENT_BIT);
        const VkDescriptorSetLayout foliageSets[] = {frameSetLayout, textureSetLayout};
        const VkPushConstantRange foliagePush{VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                                              kFoliagePushSize};
        VkPipelineLayoutCreateInfo info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
        info.setLayoutCount = 2;
        info.pSetLayouts = foliageSets;
        info.pushConstantRangeCount = 1;
        info.pPushConstantRanges = &foliagePush;
        check(vk.CreatePipelineLayout(vk.device, &info, vk.allocator, &foliageLayout), "vkCreatePipelineLayout");
        const VkPushConstantRange compositePush{VK_SHADER_STAGE_FRAGMENT_BIT, 0, kCompositePushSize};
        info.setLayoutCount = 1;
        info.pSetLayouts = &compositeSetLayout;
        info.pPushConstantRanges = &compositePush;
        check(vk.CreatePipelineLayout(vk.device, &info, vk.allocator, &compositeLayout), "vkCreatePipelineLayout");
        linearSampler = createSampler(vk, VK_FILTER_LINEAR);
        nearestSampler = createSampler(vk, VK_FILTER_NEAREST);
    } catch (...) {
        destroy(vk);
        throw;
    }
}

void SharedObjects::destroy(const VkFunctions& vk) noexcept {
    if (!vk.device) return;
    for (VkShaderModule m :
         {foliageVertex, maskVertex, maskFragment, colorFragment, fullscreenVertex, compositeFragment})
        if (m) vk.DestroyShaderModule(vk.device, m, vk.allocator);
    for (VkPipelineLayout l : {foliageLayout, compositeLayout})
        if (l) vk.DestroyPipelineLayout(vk.device, l, vk.allocator);
    for (VkDescriptorSetLayout l : {frameSetLayout, textureSetLayout, compositeSetLayout})
        if (l) vk.DestroyDescriptorSetLayout(vk.device, l, vk.allocator);
    for (VkSampler s : {linearSampler, nearestSampler})
        if (s) vk.DestroySampler(vk.device, s, vk.allocator);
    *this = {};
}

void Generation::create(const VkFunctions& vk, const MemorySource& memory, const SharedObjects& shared,
                        const GenerationKey& k, const Settings& settings, bool dynamicRendering) {
    key = k;
    try {
        if (!dynamicRendering) {
            maskPass = createPassFor(vk, Kind::Mask, k.maskFormat, k.depthFormat);
            colorPass = createPassFor(vk, Kind::Color, k.colorFormat, k.depthFormat);
            compositePass = createPassFor(vk, Kind::Composite, k.colorFormat, VK_FORMAT_UNDEFINED);
        }
        maskPipeline = createPipeline(vk, shared, Kind::Mask, maskPass, k.maskFormat, k.depthFormat, settings);
        colorPipeline = createPipeline(vk, shared, Kind::Color, colorPass, k.colorFormat, k.depthFormat, settings);
        compositePipeline =
            createPipeline(vk, shared, Kind::Composite, compositePass, k.colorFormat, VK_FORMAT_UNDEFINED, settings);
        constexpr VkImageUsageFlags usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT |
                                            VK_IMAGE_USAGE_TRANSFER_SRC_BIT;  // TRANSFER_SRC: hosts read them out
        mask = createImage(vk, memory, k.maskFormat, k.width, k.height, usage, "the mask");
        foliage = createImage(vk, memory, k.colorFormat, k.width, k.height, usage, "rt_foliage");
        const VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 3};
        VkDescriptorPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
        poolInfo.maxSets = 1;
        poolInfo.poolSizeCount = 1;
        poolInfo.pPoolSizes = &size;
        check(vk.CreateDescriptorPool(vk.device, &poolInfo, vk.allocator, &pool), "vkCreateDescriptorPool");
        VkDescriptorSetAllocateInfo allocate{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
        allocate.descriptorPool = pool;
        allocate.descriptorSetCount = 1;
        allocate.pSetLayouts = &shared.compositeSetLayout;
        check(vk.AllocateDescriptorSets(vk.device, &allocate, &compositeSet), "vkAllocateDescriptorSets");
        // rt_foliage, the mask, and the mask again where the shader's second mask target would be.
        const VkDescriptorImageInfo images[3] = {
            {shared.nearestSampler, foliage.view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL},
            {shared.nearestSampler, mask.view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL},
            {shared.nearestSampler, mask.view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL}};
        VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
        write.dstSet = compositeSet;
        write.descriptorCount = 3;
        write.descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
        write.pImageInfo = images;
        vk.UpdateDescriptorSets(vk.device, 1, &write, 0, nullptr);
    } catch (...) {
        destroy(vk, memory);
        throw;
    }
}

void Generation::destroy(const VkFunctions& vk, const MemorySource& memory) noexcept {
    for (const FrameFramebuffers& f : framebuffers) destroyFramebuffers(vk, f);
    for (VkPipeline p : {maskPipeline, colorPipeline, compositePipeline})
        if (p) vk.DestroyPipeline(vk.device, p, vk.allocator);
    for (VkRenderPass p : {maskPass, colorPass, compositePass})
        if (p) vk.DestroyRenderPass(vk.device, p, vk.allocator);
    if (pool) vk.DestroyDescriptorPool(vk.device, pool, vk.allocator);
    detail::destroy(vk, memory, mask);
    detail::destroy(vk, memory, foliage);
    *this = {};
}

const FrameFramebuffers& Generation::framebuffersFor(const VkFunctions& vk, VkImageView color, VkImageView depth,
                                                     std::uint64_t frame, Retired& retired) {
    for (FrameFramebuffers& f : framebuffers)
        if (f.hostColor == color && f.hostDepth == depth) {
            f.lastUsedFrame = frame;
            return f;
        }
    if (framebuffers.size() >= kFramebufferCacheSize) {
        const auto oldest = std::min_element(
            framebuffers.begin(), framebuffers.end(),
            [](const FrameFramebuffers& a, const FrameFramebuffers& b) { return a.lastUsedFrame < b.lastUsedFrame; });
        const FrameFramebuffers old = *oldest;
        retired.add(old.lastUsedFrame, [&vk, old] { destroyFramebuffers(vk, old); });
        framebuffers.erase(oldest);
    }
    FrameFramebuffers f;
    f.hostColor = color;
    f.hostDepth = depth;
    f.lastUsedFrame = frame;
    try {
        f.mask = createFramebuffer(vk, maskPass, {mask.view, depth}, key.width, key.height);
        f.color = createFramebuffer(vk, colorPass, {foliage.view, depth}, key.width, key.height);
        f.composite = createFramebuffer(vk, compositePass, {color}, key.width, key.height);
    } catch (...) {
        destroyFramebuffers(vk, f);
        throw;
    }
    framebuffers.push_back(f);
    return framebuffers.back();
}

}  // namespace ssam::vk::detail
