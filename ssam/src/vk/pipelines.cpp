// SPDX-License-Identifier: MIT
#include "pipelines.hpp"

#include <array>
#include <string>

#include "ssam/core/passes.hpp"
#include "failure.hpp"
#include "ssam_vk_spirv.hpp"  // generated: glslc's output of glsl_variants.cpp's sources

namespace ssam::vk::detail {

namespace {

VkShaderModule createModule(const VkFunctions& vk, const std::uint32_t* code, std::size_t bytes, const char* what) {
    VkShaderModuleCreateInfo info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
    info.codeSize = bytes;
    info.pCode = code;
    VkShaderModule module = VK_NULL_HANDLE;
    check(vk.CreateShaderModule(vk.device, &info, vk.allocator, &module), "vkCreateShaderModule", what);
    return module;
}

VkDescriptorSetLayout createSetLayout(const VkFunctions& vk, VkDescriptorType type, std::uint32_t count,
                                      VkShaderStageFlags stages) {
    std::array<VkDescriptorSetLayoutBinding, 4> bindings{};
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

// One subpass: `colorCount` colour targets of format `color` (cleared, or loaded for the
// composite; two: Rg16f's mask pair; none: the depth restore) and optionally the host's depth
// (loaded and stored, stencil too) after them. The external dependencies are the synchronization
// contract (ssam_vk.hpp): in, the host's or SSAM's previous attachment writes and SSAM's previous
// sampled reads of its intermediates (WAR); out, these attachment writes for the next pass's
// attachment use or sampling, and for the host's.
VkRenderPass createRenderPass(const VkFunctions& vk, VkFormat color, std::uint32_t colorCount, bool clearColor,
                              VkImageLayout colorFinal, VkFormat depth) {
    std::array<VkAttachmentDescription, 3> attachments{};
    std::array<VkAttachmentReference, 2> colorRefs{};
    for (std::uint32_t i = 0; i < colorCount; ++i) {
        VkAttachmentDescription& a = attachments[i];
        a.format = color;
        a.samples = VK_SAMPLE_COUNT_1_BIT;
        a.loadOp = clearColor ? VK_ATTACHMENT_LOAD_OP_CLEAR : VK_ATTACHMENT_LOAD_OP_LOAD;
        a.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
        a.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
        a.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
        a.initialLayout = clearColor ? VK_IMAGE_LAYOUT_UNDEFINED : VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
        a.finalLayout = colorFinal;
        colorRefs[i] = {i, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
    }
    VkAttachmentDescription& d = attachments[colorCount];
    d.format = depth;
    d.samples = VK_SAMPLE_COUNT_1_BIT;
    d.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;
    d.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    d.stencilLoadOp = hasStencil(depth) ? VK_ATTACHMENT_LOAD_OP_LOAD : VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    d.stencilStoreOp = hasStencil(depth) ? VK_ATTACHMENT_STORE_OP_STORE : VK_ATTACHMENT_STORE_OP_DONT_CARE;
    d.initialLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
    d.finalLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
    const VkAttachmentReference depthRef{colorCount, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
    VkSubpassDescription subpass{};
    subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
    subpass.colorAttachmentCount = colorCount;
    subpass.pColorAttachments = colorRefs.data();
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
    info.attachmentCount = colorCount + (depth != VK_FORMAT_UNDEFINED ? 1 : 0);
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

// Where the shaders' locations 0-8 (foliage.vert) come from: the host's bindings, or SSAM's
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
    add(8, layout.instanceTint, VK_FORMAT_R32G32B32A32_SFLOAT, base + 32);  // no tint: the colour's (1,1,1,1)
    return in;
}

using Kind = PassKind;

// With `pass` null (RenderingPath::DynamicRendering) the attachment formats come from
// VkPipelineRenderingCreateInfo instead.
VkPipeline createPipeline(const VkFunctions& vk, const SharedObjects& shared, Kind kind, VkRenderPass pass,
                          VkFormat colorFormat, VkFormat depthFormat, const Settings& settings,
                          const VertexLayout& layout) {
    const bool fullscreen = kind == Kind::Composite || kind == Kind::DepthRestore;
    VkPipelineShaderStageCreateInfo stages[2]{{VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO},
                                              {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO}};
    stages[0].stage = VK_SHADER_STAGE_VERTEX_BIT;
    stages[0].module = fullscreen           ? shared.fullscreenVertex
                       : kind == Kind::Mask ? shared.maskVertex
                                            : shared.foliageVertex;
    stages[0].pName = "main";
    stages[1].stage = VK_SHADER_STAGE_FRAGMENT_BIT;
    const bool maskPair = settings.maskPrecision == MaskPrecision::Rg16f;
    switch (kind) {
        case Kind::Mask: stages[1].module = maskPair ? shared.maskPairFragment : shared.maskFragment; break;
        case Kind::Color: stages[1].module = shared.colorFragment; break;
        case Kind::Composite: stages[1].module = shared.compositeFragment; break;
        case Kind::DepthRestore: stages[1].module = shared.restoreFragment; break;
    }
    stages[1].pName = "main";
    const VertexInput input = fullscreen ? VertexInput{} : vertexInput(layout, kind == Kind::Color);
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
    blending.attachmentCount = state.colorAttachmentCount;
    blending.pAttachments = state.blendAttachments;
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
    info.pDepthStencilState = kind == Kind::Composite ? nullptr : &state.depthStencil;
    info.pColorBlendState = &blending;
    info.pDynamicState = &dynamic;
    info.layout = kind == Kind::Composite      ? shared.compositeLayout
                  : kind == Kind::DepthRestore ? shared.restoreLayout
                                               : shared.foliageLayout;
    info.renderPass = pass;
    VkPipelineRenderingCreateInfo rendering{VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO};
    const VkFormat colorFormats[2] = {colorFormat, colorFormat};
    rendering.colorAttachmentCount = state.colorAttachmentCount;
    rendering.pColorAttachmentFormats = colorFormats;
    rendering.depthAttachmentFormat = depthFormat;
    rendering.stencilAttachmentFormat = hasStencil(depthFormat) ? depthFormat : VK_FORMAT_UNDEFINED;
    if (!pass) info.pNext = &rendering;
    VkPipeline pipeline = VK_NULL_HANDLE;
    check(vk.CreateGraphicsPipelines(vk.device, VK_NULL_HANDLE, 1, &info, vk.allocator, &pipeline),
          kind == Kind::Mask           ? "vkCreateGraphicsPipelines, mask"
          : kind == Kind::DepthRestore ? "vkCreateGraphicsPipelines, depth restore"
                                       : "vkCreateGraphicsPipelines");
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

}  // namespace

namespace {

VkBlendFactor toVk(core::BlendFactor factor) {
    switch (factor) {
        case core::BlendFactor::Zero: return VK_BLEND_FACTOR_ZERO;
        case core::BlendFactor::One: return VK_BLEND_FACTOR_ONE;
        case core::BlendFactor::SrcAlpha: return VK_BLEND_FACTOR_SRC_ALPHA;
        case core::BlendFactor::OneMinusSrcAlpha: return VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
    }
    return VK_BLEND_FACTOR_ONE;
}

VkBlendOp toVk(core::BlendOp op) { return op == core::BlendOp::Max ? VK_BLEND_OP_MAX : VK_BLEND_OP_ADD; }

const core::PassDescription& passOf(const core::PassPlan& plan, PassKind kind) {
    switch (kind) {
        case Kind::Mask: return plan.mask;
        case Kind::Color: return plan.color;
        case Kind::Composite: return plan.composite;
        case Kind::DepthRestore: return plan.depthRestore;
    }
    return plan.mask;
}

}  // namespace

// The core's pass (core/passes.hpp) as Vulkan fixed-function state. Vulkan writes depth only with
// the depth test enabled: a pass that writes without testing (the depth restore) tests ALWAYS.
void fixedState(PassKind kind, const Settings& settings, PipelineState& state) {
    const core::PassPlan plan = core::describePasses(settings);
    const core::PassDescription& pass = passOf(plan, kind);
    state.rasterization = {VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
    state.rasterization.polygonMode = VK_POLYGON_MODE_FILL;
    state.rasterization.cullMode = pass.cullBackFaces ? VK_CULL_MODE_BACK_BIT : VK_CULL_MODE_NONE;
    state.rasterization.frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
    state.rasterization.lineWidth = 1.0f;
    state.multisample = {VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
    state.multisample.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
    state.depthStencil = {VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
    state.depthStencil.depthTestEnable = pass.depthTest || pass.depthWrite ? VK_TRUE : VK_FALSE;
    state.depthStencil.depthWriteEnable = pass.depthWrite ? VK_TRUE : VK_FALSE;
    state.depthStencil.depthCompareOp = pass.depthTest ? toVk(pass.depthCompare) : VK_COMPARE_OP_ALWAYS;
    state.colorAttachmentCount = static_cast<std::uint32_t>(pass.colorTargetCount);
    for (int t = 0; t < 2; ++t) {
        VkPipelineColorBlendAttachmentState& b = state.blendAttachments[t];
        b = {};
        b.colorWriteMask =
            VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT | VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT;
        const core::TargetBlend& blend = pass.colorTargets[t].blend;
        if (t >= pass.colorTargetCount || !blend.enabled) continue;
        b.blendEnable = VK_TRUE;
        b.srcColorBlendFactor = toVk(blend.srcColor);
        b.dstColorBlendFactor = toVk(blend.dstColor);
        b.colorBlendOp = toVk(blend.colorOp);
        b.srcAlphaBlendFactor = toVk(blend.srcAlpha);
        b.dstAlphaBlendFactor = toVk(blend.dstAlpha);
        b.alphaBlendOp = toVk(blend.alphaOp);
    }
}

VkRenderPass createPassFor(const VkFunctions& vk, PassKind pass, VkFormat target, VkFormat depth) {
    if (pass == Kind::Composite)
        return createRenderPass(vk, target, 1, false, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_FORMAT_UNDEFINED);
    if (pass == Kind::DepthRestore)
        return createRenderPass(vk, VK_FORMAT_UNDEFINED, 0, false, VK_IMAGE_LAYOUT_UNDEFINED, depth);
    const std::uint32_t targets = pass == Kind::Mask && target == kMaskPairFormat ? 2 : 1;
    return createRenderPass(vk, target, targets, true, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, depth);
}

void SharedObjects::create(const VkFunctions& vk) {
    try {
        foliageVertex = createModule(vk, spirv::kFoliageVert, spirv::kFoliageVertSize, "foliage.vert");
        maskVertex = createModule(vk, spirv::kMaskVert, spirv::kMaskVertSize, "mask.vert");
        maskFragment = createModule(vk, spirv::kMaskFrag, spirv::kMaskFragSize, "mask.frag");
        maskPairFragment = createModule(vk, spirv::kMaskpairFrag, spirv::kMaskpairFragSize, "maskpair.frag");
        restoreFragment = createModule(vk, spirv::kRestoreFrag, spirv::kRestoreFragSize, "restore.frag");
        colorFragment = createModule(vk, spirv::kColorFrag, spirv::kColorFragSize, "color.frag");
        fullscreenVertex = createModule(vk, spirv::kFullscreenVert, spirv::kFullscreenVertSize, "fullscreen.vert");
        compositeFragment = createModule(vk, spirv::kCompositeFrag, spirv::kCompositeFragSize, "composite.frag");
        frameSetLayout = createSetLayout(vk, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1,
                                         VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT);
        textureSetLayout =
            createSetLayout(vk, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_FRAGMENT_BIT);
        compositeSetLayout =
            createSetLayout(vk, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 3, VK_SHADER_STAGE_FRAGMENT_BIT);
        restoreSetLayout =
            createSetLayout(vk, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 4, VK_SHADER_STAGE_FRAGMENT_BIT);
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
        const VkPushConstantRange restorePush{VK_SHADER_STAGE_FRAGMENT_BIT, 0, kRestorePushSize};
        info.pSetLayouts = &restoreSetLayout;
        info.pPushConstantRanges = &restorePush;
        check(vk.CreatePipelineLayout(vk.device, &info, vk.allocator, &restoreLayout), "vkCreatePipelineLayout");
        linearSampler = createSampler(vk, VK_FILTER_LINEAR);
        nearestSampler = createSampler(vk, VK_FILTER_NEAREST);
    } catch (...) {
        destroy(vk);
        throw;
    }
}

void SharedObjects::destroy(const VkFunctions& vk) noexcept {
    if (!vk.device) return;
    for (VkShaderModule m : {foliageVertex, maskVertex, maskFragment, maskPairFragment, colorFragment, fullscreenVertex,
                             compositeFragment, restoreFragment})
        if (m) vk.DestroyShaderModule(vk.device, m, vk.allocator);
    for (VkPipelineLayout l : {foliageLayout, compositeLayout, restoreLayout})
        if (l) vk.DestroyPipelineLayout(vk.device, l, vk.allocator);
    for (VkDescriptorSetLayout l : {frameSetLayout, textureSetLayout, compositeSetLayout, restoreSetLayout})
        if (l) vk.DestroyDescriptorSetLayout(vk.device, l, vk.allocator);
    for (VkSampler s : {linearSampler, nearestSampler})
        if (s) vk.DestroySampler(vk.device, s, vk.allocator);
    *this = {};
}

void Generation::create(const VkFunctions& vk, const MemorySource& memory, const SharedObjects& shared,
                        const GenerationKey& k, const Settings& settings, const VertexLayout& layout,
                        bool dynamicRendering) {
    key = k;
    try {
        if (!dynamicRendering) {
            maskPass = createPassFor(vk, Kind::Mask, k.maskFormat, k.depthFormat);
            colorPass = createPassFor(vk, Kind::Color, k.colorFormat, k.depthFormat);
            compositePass = createPassFor(vk, Kind::Composite, k.colorFormat, VK_FORMAT_UNDEFINED);
            if (k.depthRestore) restorePass = createPassFor(vk, Kind::DepthRestore, VK_FORMAT_UNDEFINED, k.depthFormat);
        }
        maskPipeline = createPipeline(vk, shared, Kind::Mask, maskPass, k.maskFormat, k.depthFormat, settings, layout);
        colorPipeline =
            createPipeline(vk, shared, Kind::Color, colorPass, k.colorFormat, k.depthFormat, settings, layout);
        compositePipeline = createPipeline(vk, shared, Kind::Composite, compositePass, k.colorFormat,
                                           VK_FORMAT_UNDEFINED, settings, layout);
        if (k.depthRestore)
            restorePipeline = createPipeline(vk, shared, Kind::DepthRestore, restorePass, VK_FORMAT_UNDEFINED,
                                             k.depthFormat, settings, layout);
        constexpr VkImageUsageFlags usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT |
                                            VK_IMAGE_USAGE_TRANSFER_SRC_BIT;  // TRANSFER_SRC: hosts read them out
        mask = createImage(vk, memory, k.maskFormat, k.width, k.height, usage, "the mask");
        if (k.maskPair()) maskAdd = createImage(vk, memory, k.maskFormat, k.width, k.height, usage, "the ADD mask");
        foliage = createImage(vk, memory, k.colorFormat, k.width, k.height, usage, "rt_foliage");
        if (k.depthRestore)  // the depth aspect only: the stencil is never copied
            savedDepth = createImage(vk, memory, k.depthFormat, k.width, k.height,
                                     VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_SAMPLED_BIT,
                                     "the saved opaque depth", VK_IMAGE_ASPECT_DEPTH_BIT);
        const VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 3 + 4};
        VkDescriptorPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
        poolInfo.maxSets = 2;
        poolInfo.poolSizeCount = 1;
        poolInfo.pPoolSizes = &size;
        check(vk.CreateDescriptorPool(vk.device, &poolInfo, vk.allocator, &pool), "vkCreateDescriptorPool");
        VkDescriptorSetAllocateInfo allocate{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
        allocate.descriptorPool = pool;
        allocate.descriptorSetCount = 1;
        allocate.pSetLayouts = &shared.compositeSetLayout;
        check(vk.AllocateDescriptorSets(vk.device, &allocate, &compositeSet), "vkAllocateDescriptorSets");
        // rt_foliage, the mask, the ADD mask (Rg16f; else the mask again, unread) and, for the depth
        // restore, the saved opaque depth.
        const VkDescriptorImageInfo images[4] = {
            {shared.nearestSampler, foliage.view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL},
            {shared.nearestSampler, mask.view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL},
            {shared.nearestSampler, k.maskPair() ? maskAdd.view : mask.view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL},
            {shared.nearestSampler, savedDepth.view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL}};
        VkWriteDescriptorSet writes[2] = {{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET},
                                          {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET}};
        writes[0].dstSet = compositeSet;
        writes[0].descriptorCount = 3;
        writes[0].descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
        writes[0].pImageInfo = images;
        if (k.depthRestore) {
            allocate.pSetLayouts = &shared.restoreSetLayout;
            check(vk.AllocateDescriptorSets(vk.device, &allocate, &restoreSet), "vkAllocateDescriptorSets");
            writes[1] = writes[0];
            writes[1].dstSet = restoreSet;
            writes[1].descriptorCount = 4;
        }
        vk.UpdateDescriptorSets(vk.device, k.depthRestore ? 2 : 1, writes, 0, nullptr);
    } catch (...) {
        destroy(vk, memory);
        throw;
    }
}

void destroyFramebuffers(const VkFunctions& vk, const FrameFramebuffers& f) noexcept {
    for (VkFramebuffer fb : {f.mask, f.color, f.composite, f.restore})
        if (fb) vk.DestroyFramebuffer(vk.device, fb, vk.allocator);
}

void Generation::destroy(const VkFunctions& vk, const MemorySource& memory) noexcept {
    for (VkPipeline p : {maskPipeline, colorPipeline, compositePipeline, restorePipeline})
        if (p) vk.DestroyPipeline(vk.device, p, vk.allocator);
    for (VkRenderPass p : {maskPass, colorPass, compositePass, restorePass})
        if (p) vk.DestroyRenderPass(vk.device, p, vk.allocator);
    if (pool) vk.DestroyDescriptorPool(vk.device, pool, vk.allocator);
    for (Image* image : {&mask, &maskAdd, &foliage, &savedDepth}) detail::destroy(vk, memory, *image);
    *this = {};
}

FrameFramebuffers Generation::createFramebuffers(const VkFunctions& vk, VkImageView color, VkImageView depth) const {
    FrameFramebuffers f;
    try {
        f.mask = key.maskPair()
                     ? createFramebuffer(vk, maskPass, {mask.view, maskAdd.view, depth}, key.width, key.height)
                     : createFramebuffer(vk, maskPass, {mask.view, depth}, key.width, key.height);
        f.color = createFramebuffer(vk, colorPass, {foliage.view, depth}, key.width, key.height);
        f.composite = createFramebuffer(vk, compositePass, {color}, key.width, key.height);
        if (restorePass) f.restore = createFramebuffer(vk, restorePass, {depth}, key.width, key.height);
    } catch (...) {
        destroyFramebuffers(vk, f);
        throw;
    }
    return f;
}

}  // namespace ssam::vk::detail
