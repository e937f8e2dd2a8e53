// SPDX-License-Identifier: MIT
// ssam::vk with the host's own pipelines (way b): the Vulkan host of vk_common/ draws its cards
// with its own shaders (vk_host_shaders/*.vert, *.frag, compiled by glslc when it is built), whose
// vertex stage bends them in the wind, inside SSAM's mask and colour passes
// ([Hathaway 2010] §3.5.2-3.5.3). SSAM hands out the fixed-function state those pipelines must be
// created with (ScreenSpaceAlphaMaskVk::pipelineState: blend, depth-stencil, rasterization, the
// render pass or attachment formats), and the host rebuilds them when pipelineStateVersion() moves.
//
//   ssam_vk_host_shaders [--out frame.png] [--mask mask.png] [--frames N] [--validation]
//                        [--dynamic-rendering] [--present] [--wind AMPLITUDE]
//       as ssam_vk_embedding; --wind moves a card's top AMPLITUDE world units in x (default 0.3;
//       0 draws what the built-in programs draw)
// Exit codes: vk_common/vk_example.hpp.
#include <algorithm>
#include <array>
#include <cstring>

#include "host_spirv.hpp"  // generated: glslc's output of wind.vert, mask.frag, color.frag
#include "vk_example.hpp"

namespace {

using namespace vk_example;

// The host's push constants (the shaders' `Host` block).
struct HostConstants {
    float viewProj[16];
    float tint[4];
    float wind;
    float alphaReference;
};

class HostPipelines final : public FoliageRecorder {
public:
    HostPipelines(HostScene& scene, const Arguments& args)
        : scene_(scene), device_(scene.host.device), wind_(args.wind) {
        // The leaf texture with the host's own sampler, in the host's own descriptor set.
        VkSamplerCreateInfo sampler{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
        sampler.magFilter = sampler.minFilter = VK_FILTER_LINEAR;
        sampler.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
        sampler.addressModeU = sampler.addressModeV = sampler.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
        check(vkCreateSampler(device_, &sampler, nullptr, &sampler_), "vkCreateSampler");
        const VkDescriptorSetLayoutBinding binding{0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1,
                                                   VK_SHADER_STAGE_FRAGMENT_BIT, nullptr};
        VkDescriptorSetLayoutCreateInfo setLayout{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
        setLayout.bindingCount = 1;
        setLayout.pBindings = &binding;
        check(vkCreateDescriptorSetLayout(device_, &setLayout, nullptr, &setLayout_), "vkCreateDescriptorSetLayout");
        const VkPushConstantRange push{VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                                       sizeof(HostConstants)};
        VkPipelineLayoutCreateInfo layout{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
        layout.setLayoutCount = 1;
        layout.pSetLayouts = &setLayout_;
        layout.pushConstantRangeCount = 1;
        layout.pPushConstantRanges = &push;
        check(vkCreatePipelineLayout(device_, &layout, nullptr, &layout_), "vkCreatePipelineLayout");
        const VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1};
        VkDescriptorPoolCreateInfo pool{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
        pool.maxSets = 1;
        pool.poolSizeCount = 1;
        pool.pPoolSizes = &size;
        check(vkCreateDescriptorPool(device_, &pool, nullptr, &pool_), "vkCreateDescriptorPool");
        VkDescriptorSetAllocateInfo allocate{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
        allocate.descriptorPool = pool_;
        allocate.descriptorSetCount = 1;
        allocate.pSetLayouts = &setLayout_;
        check(vkAllocateDescriptorSets(device_, &allocate, &set_), "vkAllocateDescriptorSets");
        const VkDescriptorImageInfo image{sampler_, scene.leaf.view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
        VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
        write.dstSet = set_;
        write.descriptorCount = 1;
        write.descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
        write.pImageInfo = &image;
        vkUpdateDescriptorSets(device_, 1, &write, 0, nullptr);
        vertex_ =
            scene.host.createShaderModule(host_spirv::kWindVert, host_spirv::kWindVertSize, "vkCreateShaderModule");
        fragments_[0] =
            scene.host.createShaderModule(host_spirv::kMaskFrag, host_spirv::kMaskFragSize, "vkCreateShaderModule");
        fragments_[1] =
            scene.host.createShaderModule(host_spirv::kColorFrag, host_spirv::kColorFragSize, "vkCreateShaderModule");
    }
    ~HostPipelines() override {
        vkDeviceWaitIdle(device_);
        destroyPipelines();
        for (VkShaderModule m : {vertex_, fragments_[0], fragments_[1]}) vkDestroyShaderModule(device_, m, nullptr);
        vkDestroyDescriptorPool(device_, pool_, nullptr);
        vkDestroyPipelineLayout(device_, layout_, nullptr);
        vkDestroyDescriptorSetLayout(device_, setLayout_, nullptr);
        vkDestroySampler(device_, sampler_, nullptr);
    }
    HostPipelines(const HostPipelines&) = delete;
    HostPipelines& operator=(const HostPipelines&) = delete;

    void record(ssam::vk::ScreenSpaceAlphaMaskVk& ssam, const ssam::vk::FrameDesc& frame) override {
        // SSAM's state changed (a setSettings of the depth test or the mask's format): new pipelines.
        // (An engine retires the old ones until its frames in flight complete; this one waits.)
        if (pipelines_[0] == VK_NULL_HANDLE || version_ != ssam.pipelineStateVersion()) {
            vkDeviceWaitIdle(device_);
            destroyPipelines();
            for (ssam::vk::FoliagePass pass : {ssam::vk::FoliagePass::Mask, ssam::vk::FoliagePass::Color})
                pipelines_[int(pass)] = createPipeline(ssam, pass, frame.colorFormat, frame.depthFormat);
        }
        ssam::vk::FrameReport report;
        checkSsam(ssam, ssam.beginFrame(frame, &report), "ssam::vk beginFrame");
        if (!report.foliageInView) return;  // no card in view: the frame is over, nothing was recorded
        for (ssam::vk::FoliagePass pass : {ssam::vk::FoliagePass::Mask, ssam::vk::FoliagePass::Color}) {
            ssam::vk::PassInfo info;
            const bool mask = pass == ssam::vk::FoliagePass::Mask;
            checkSsam(ssam, mask ? ssam.beginMaskPass(&info) : ssam.beginColorPass(&info), "ssam::vk begin pass");
            // Inside SSAM's pass: the host's pipeline, set and constants; the same draws both times.
            vkCmdBindPipeline(info.commandBuffer, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines_[int(pass)]);
            vkCmdBindDescriptorSets(info.commandBuffer, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_, 0, 1, &set_, 0,
                                    nullptr);
            HostConstants constants{};
            std::memcpy(constants.viewProj, frame.viewProj, sizeof constants.viewProj);
            constants.wind = wind_;
            constants.alphaReference = info.alphaReference;
            scene_.drawCards(info.commandBuffer, [&](const float tint[4]) {
                std::copy(tint, tint + 4, constants.tint);
                vkCmdPushConstants(info.commandBuffer, layout_,
                                   VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof constants,
                                   &constants);
            });
            checkSsam(ssam, mask ? ssam.endMaskPass() : ssam.endColorPass(), "ssam::vk end pass");
        }
        checkSsam(ssam, ssam.composite(), "ssam::vk composite");
    }

private:
    // The host's pipeline for `pass`: its shaders and vertex layout, SSAM's fixed-function state.
    VkPipeline createPipeline(const ssam::vk::ScreenSpaceAlphaMaskVk& ssam, ssam::vk::FoliagePass pass,
                              VkFormat colorFormat, VkFormat depthFormat) {
        ssam::vk::PipelineState state;
        checkSsam(ssam, ssam.pipelineState(pass, colorFormat, depthFormat, &state), "ssam::vk pipelineState");
        version_ = state.version;
        const auto stages = shaderStages(vertex_, fragments_[int(pass)]);
        const VkVertexInputBindingDescription binding{0, sizeof(Vertex), VK_VERTEX_INPUT_RATE_VERTEX};
        const VkVertexInputAttributeDescription attributes[2] = {{0, 0, VK_FORMAT_R32G32B32_SFLOAT, 0},
                                                                 {1, 0, VK_FORMAT_R32G32_SFLOAT, 3 * sizeof(float)}};
        VkPipelineVertexInputStateCreateInfo vertexInput{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
        vertexInput.vertexBindingDescriptionCount = 1;
        vertexInput.pVertexBindingDescriptions = &binding;
        vertexInput.vertexAttributeDescriptionCount = 2;
        vertexInput.pVertexAttributeDescriptions = attributes;
        VkPipelineInputAssemblyStateCreateInfo assembly{VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
        assembly.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
        VkPipelineViewportStateCreateInfo viewport{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
        viewport.viewportCount = viewport.scissorCount = 1;
        VkPipelineColorBlendStateCreateInfo blend{VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
        blend.attachmentCount = state.colorAttachmentCount;
        blend.pAttachments = state.blendAttachments;
        const VkDynamicState dynamics[] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};  // SSAM sets them
        VkPipelineDynamicStateCreateInfo dynamic{VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO};
        dynamic.dynamicStateCount = 2;
        dynamic.pDynamicStates = dynamics;
        VkPipelineRenderingCreateInfo rendering{VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO};
        rendering.colorAttachmentCount = state.colorAttachmentCount;
        rendering.pColorAttachmentFormats = state.colorAttachmentFormats;
        rendering.depthAttachmentFormat = state.depthAttachmentFormat;
        rendering.stencilAttachmentFormat = state.stencilAttachmentFormat;
        VkGraphicsPipelineCreateInfo info{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO};
        info.pNext = state.renderPass ? nullptr : &rendering;  // dynamic rendering: the formats
        info.stageCount = 2;
        info.pStages = stages.data();
        info.pVertexInputState = &vertexInput;
        info.pInputAssemblyState = &assembly;
        info.pViewportState = &viewport;
        info.pRasterizationState = &state.rasterization;
        info.pMultisampleState = &state.multisample;
        info.pDepthStencilState = &state.depthStencil;
        info.pColorBlendState = &blend;
        info.pDynamicState = &dynamic;
        info.layout = layout_;
        info.renderPass = state.renderPass;
        VkPipeline pipeline = VK_NULL_HANDLE;
        check(vkCreateGraphicsPipelines(device_, VK_NULL_HANDLE, 1, &info, nullptr, &pipeline),
              "vkCreateGraphicsPipelines");
        return pipeline;
    }

    void destroyPipelines() {
        for (VkPipeline& p : pipelines_) {
            if (p) vkDestroyPipeline(device_, p, nullptr);
            p = VK_NULL_HANDLE;
        }
    }

    HostScene& scene_;
    VkDevice device_;
    float wind_;
    VkSampler sampler_ = VK_NULL_HANDLE;
    VkDescriptorSetLayout setLayout_ = VK_NULL_HANDLE;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    VkDescriptorPool pool_ = VK_NULL_HANDLE;
    VkDescriptorSet set_ = VK_NULL_HANDLE;
    VkShaderModule vertex_ = VK_NULL_HANDLE;
    std::array<VkShaderModule, 2> fragments_{};
    std::array<VkPipeline, 2> pipelines_{};  // FoliagePass::Mask, FoliagePass::Color
    std::uint64_t version_ = 0;
};

}  // namespace

int main(int argc, char** argv) {
    return runExample({"ssam_vk_host_shaders", true}, argc, argv,
                      [](HostScene& scene, ssam::vk::ScreenSpaceAlphaMaskVk&, const Arguments& args) {
                          return std::make_unique<HostPipelines>(scene, args);
                      });
}
