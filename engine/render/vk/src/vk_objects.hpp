// SPDX-License-Identifier: MIT
#pragma once
// What the Vulkan backend keeps behind its handles, and the state it tracks per image.
#include <cstdint>
#include <array>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "engine/render/buffer.hpp"
#include "engine/render/pipeline.hpp"
#include "engine/render/program_desc.hpp"
#include "engine/render/shader_interface.hpp"
#include "engine/render/texture.hpp"

namespace engine::render::vk {

// The last use of an image, for the barrier before the next one: its layout, the write not yet
// made visible (stage + access), the stages that have seen it, and the reads since.
struct ImageState {
    VkImageLayout layout = VK_IMAGE_LAYOUT_UNDEFINED;
    VkPipelineStageFlags writeStages = 0;
    VkAccessFlags writeAccess = 0;
    VkPipelineStageFlags visibleTo = 0;
    VkPipelineStageFlags readStages = 0;
};

struct VulkanTexture {
    TextureDesc desc;
    VkImage image = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    VkImageView view = VK_NULL_HANDLE;
    VkFormat format = VK_FORMAT_UNDEFINED;
    VkImageAspectFlags aspect = VK_IMAGE_ASPECT_COLOR_BIT;
    int actualSamples = 1;    // what the device supports at or above desc.samples
    std::uint64_t bytes = 0;  // its memory's size
    ImageState state;
};

struct VulkanBuffer {
    BufferDesc desc;
    VkBuffer buffer = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    std::byte* mapped = nullptr;  // host-visible and coherent, mapped for its lifetime
    std::uint64_t lastUse = 0;    // serial of the last submission that reads it
};

// A program compiled for Vulkan, with its pipeline layout and the pipelines made for it (one
// per resolved state and target formats, made at the first draw that needs each).
struct VulkanProgram {
    VkDevice device = VK_NULL_HANDLE;
    std::shared_ptr<const ProgramDesc> desc;
    UniformBlockLayout block;
    VkShaderModule vertex = VK_NULL_HANDLE;
    // The fragment stage per number of colour targets (0..4): outputs without an attachment are
    // plain variables there, since validation reports a written output nothing consumes.
    // The four-target one is made with the program (so a body that does not compile fails
    // then), the others at the first pass with that many targets.
    mutable std::array<VkShaderModule, kMaxColorTargets + 1> fragments{};
    VkDescriptorSetLayout textureLayout = VK_NULL_HANDLE;  // set 0: a combined image sampler per texture unit
    VkPipelineLayout layout = VK_NULL_HANDLE;
    mutable std::map<std::vector<std::uint8_t>, VkPipeline> pipelines;

    VulkanProgram() = default;
    VulkanProgram(const VulkanProgram&) = delete;
    VulkanProgram& operator=(const VulkanProgram&) = delete;
    ~VulkanProgram();
};

// An occlusion query's slot in the driver's query pool.
struct VulkanQuery {
    std::string name;  // for messages
    std::uint32_t slot = 0;
};

}  // namespace engine::render::vk
