// SPDX-License-Identifier: MIT
// Vulkan driver: textures (images, their uploads and zero fill), buffers (host-visible,
// renamed when a submission may still read them), programs and pipelines, occlusion queries.
#include <algorithm>
#include <cmath>
#include <cstring>

#include "engine/core/error.hpp"
#include "engine/core/log.hpp"
#include "engine/render/glsl/standard_programs.hpp"
#include "engine/render/memory_budget.hpp"
#include "engine/render/texel_codec.hpp"
#include "vk_backend_impl.hpp"

namespace engine::render::vk {
namespace {

VkFormat vkFormat(Format format) {
    switch (format) {
        case Format::RGBA8_UNORM: return VK_FORMAT_R8G8B8A8_UNORM;
        case Format::RGBA8_SRGB: return VK_FORMAT_R8G8B8A8_SRGB;
        case Format::R8_UNORM: return VK_FORMAT_R8_UNORM;
        case Format::RG8_UNORM: return VK_FORMAT_R8G8_UNORM;
        case Format::RGBA16F: return VK_FORMAT_R16G16B16A16_SFLOAT;
        case Format::RG16F: return VK_FORMAT_R16G16_SFLOAT;
        case Format::R16F: return VK_FORMAT_R16_SFLOAT;
        case Format::RGBA32F: return VK_FORMAT_R32G32B32A32_SFLOAT;
        case Format::R32F: return VK_FORMAT_R32_SFLOAT;
        case Format::D32F: return VK_FORMAT_D32_SFLOAT;
    }
    return VK_FORMAT_R8G8B8A8_UNORM;
}

}  // namespace

// The least sample count the device offers at or above `wanted` for this format as an
// attachment and a sampled image, as GL drivers do (llvmpipe turns 2 into 4); none: refused.
int VulkanDriverImpl::supportedSamples(VkFormat format, bool depth, int wanted, const std::string& what) const {
    const VkPhysicalDeviceLimits& l = context_->properties.limits;
    VkSampleCountFlags counts = (depth ? l.framebufferDepthSampleCounts : l.framebufferColorSampleCounts) &
                                (depth ? l.sampledImageDepthSampleCounts : l.sampledImageColorSampleCounts);
    VkImageFormatProperties p{};
    if (vkGetPhysicalDeviceImageFormatProperties(
            context_->physical, format, VK_IMAGE_TYPE_2D, VK_IMAGE_TILING_OPTIMAL,
            VK_IMAGE_USAGE_SAMPLED_BIT |
                (depth ? VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT : VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT),
            0, &p) == VK_SUCCESS)
        counts &= p.sampleCounts;
    int best = 0;
    for (int s = 64; s >= wanted; s /= 2)
        if (counts & VkSampleCountFlags(s)) best = s;
    if (!best) {
        int most = 1;
        for (int s = 1; s <= 64; s *= 2)
            if (counts & VkSampleCountFlags(s)) most = s;
        throw Error(what + ": " + std::to_string(wanted) + " samples exceed this Vulkan device's " +
                    std::to_string(most) + " (" + context_->info.device + ")");
    }
    return best;
}

void VulkanDriverImpl::checkTexture(const TextureDesc& desc, const TextureData* data, const std::string& what) {
    if (desc.samples > 1) supportedSamples(vkFormat(desc.format), formatInfo(desc.format).isDepth, desc.samples, what);
    if (desc.samples > 1 && data && !data->levels.empty())
        throw Error(what + ": initial data for a multisampled texture (the Vulkan backend cannot upload samples)");
    checkDeviceLimits(desc, what);
}

VkImageCreateInfo VulkanDriverImpl::imageInfo(const TextureDesc& desc, int actualSamples) const {
    const bool depth = formatInfo(desc.format).isDepth;
    VkImageCreateInfo ci{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    ci.imageType = VK_IMAGE_TYPE_2D;
    ci.format = vkFormat(desc.format);
    ci.extent = {std::uint32_t(desc.width), std::uint32_t(desc.height), 1};
    ci.mipLevels = std::uint32_t(desc.samples > 1 ? 1 : desc.mipLevels);
    ci.arrayLayers = 1;
    ci.samples = VkSampleCountFlagBits(actualSamples);
    ci.tiling = VK_IMAGE_TILING_OPTIMAL;
    ci.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    if (actualSamples == 1) ci.usage |= VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    if (desc.usage & UsageRenderTarget)
        ci.usage |= depth ? VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT : VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT;
    ci.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    ci.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    return ci;
}

// The image's own figure (padding, samples), known before it is made (Vulkan 1.3's
// vkGetDeviceImageMemoryRequirements), for the device's memory budget.
std::uint64_t VulkanDriverImpl::textureFootprint(const TextureDesc& desc) const {
    const int actual = desc.samples > 1
                           ? supportedSamples(vkFormat(desc.format), formatInfo(desc.format).isDepth, desc.samples, "")
                           : 1;
    const VkImageCreateInfo ci = imageInfo(desc, actual);
    VkDeviceImageMemoryRequirements info{VK_STRUCTURE_TYPE_DEVICE_IMAGE_MEMORY_REQUIREMENTS};
    info.pCreateInfo = &ci;
    VkMemoryRequirements2 req{VK_STRUCTURE_TYPE_MEMORY_REQUIREMENTS_2};
    vkGetDeviceImageMemoryRequirements(context_->device, &info, &req);
    return req.memoryRequirements.size;
}

NativeId VulkanDriverImpl::createTexture(const TextureDesc& desc, const TextureData* data, const std::string& what) {
    const bool depth = formatInfo(desc.format).isDepth;
    VulkanTexture t;
    t.desc = desc;
    t.format = vkFormat(desc.format);
    t.aspect = depth ? VK_IMAGE_ASPECT_DEPTH_BIT : VK_IMAGE_ASPECT_COLOR_BIT;
    t.actualSamples = desc.samples > 1 ? supportedSamples(t.format, depth, desc.samples, what) : 1;
    const VkImageCreateInfo ci = imageInfo(desc, t.actualSamples);
    const VkDevice device = context_->device;
    check(vkCreateImage(device, &ci, nullptr, &t.image), what + ": creating the image");
    try {
        VkMemoryRequirements req;
        vkGetImageMemoryRequirements(device, t.image, &req);
        VkMemoryAllocateInfo ai{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
        ai.allocationSize = req.size;
        ai.memoryTypeIndex = context_->memoryType(req.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, what);
        check(vkAllocateMemory(device, &ai, nullptr, &t.memory),
              what + ": allocating " + std::to_string(req.size) + " bytes for " + describeSize(desc));
        t.bytes = req.size;
        heldBytes_ += t.bytes;
        check(vkBindImageMemory(device, t.image, t.memory, 0), what + ": binding memory");
        VkImageViewCreateInfo vci{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
        vci.image = t.image;
        vci.viewType = VK_IMAGE_VIEW_TYPE_2D;
        vci.format = t.format;
        vci.subresourceRange = {t.aspect, 0, ci.mipLevels, 0, 1};
        check(vkCreateImageView(device, &vci, nullptr, &t.view), what + ": creating its view");
        upload(t, data);
    } catch (...) {
        destroyTextureObjects(t);
        throw;
    }
    ++counters_.imagesCreated;
    return textures_.add(std::move(t));
}

// Initial contents: the given levels and the generated ones (texel_codec, the soft backend's
// rounding), or zero bytes as the soft backend starts from (Vulkan leaves new images undefined).
void VulkanDriverImpl::upload(VulkanTexture& t, const TextureData* data) {
    const TextureDesc& desc = t.desc;
    const VkCommandBuffer cmd = frames_->cmd();
    const std::uint32_t levels = std::uint32_t(desc.samples > 1 ? 1 : desc.mipLevels);
    use(cmd, t, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
        true);
    if (!data || data->levels.empty()) {
        const VkImageSubresourceRange range{t.aspect, 0, levels, 0, 1};
        if (t.aspect == VK_IMAGE_ASPECT_DEPTH_BIT) {
            const VkClearDepthStencilValue zero{0.0f, 0};
            vkCmdClearDepthStencilImage(cmd, t.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &zero, 1, &range);
        } else {
            const VkClearColorValue zero{};
            vkCmdClearColorImage(cmd, t.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &zero, 1, &range);
        }
        return;
    }
    std::vector<std::byte> previous;
    int previousWidth = 0, previousHeight = 0;
    for (std::uint32_t level = 0; level < levels; ++level) {
        const int w = std::max(1, desc.width >> level), h = std::max(1, desc.height >> level);
        std::vector<std::byte> stored =
            level < data->levels.size() ? toStored(desc.format, data->levels[level], std::size_t(w) * std::size_t(h))
                                        : generateMip(desc.format, previous, previousWidth, previousHeight, w, h);
        const ArenaAllocation staging = frames_->allocate(stored.size(), 16);
        std::memcpy(staging.data, stored.data(), stored.size());
        VkBufferImageCopy copy{};
        copy.bufferOffset = staging.offset;
        copy.imageSubresource = {t.aspect, level, 0, 1};
        copy.imageExtent = {std::uint32_t(w), std::uint32_t(h), 1};
        vkCmdCopyBufferToImage(cmd, staging.buffer, t.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &copy);
        previous = std::move(stored);
        previousWidth = w, previousHeight = h;
    }
}

void VulkanDriverImpl::destroyTextureObjects(const VulkanTexture& t) {
    const VkDevice device = context_->device;
    if (t.view) vkDestroyImageView(device, t.view, nullptr);
    if (t.image) vkDestroyImage(device, t.image, nullptr);
    if (t.memory) {
        vkFreeMemory(device, t.memory, nullptr);
        heldBytes_ -= t.bytes;
    }
}

// The device's own caps beyond the engine's (validateTexture): an image side over
// maxImageDimension2D, a render target over the framebuffer limits.
void VulkanDriverImpl::checkDeviceLimits(const TextureDesc& desc, const std::string& what) const {
    const VkPhysicalDeviceLimits& limits = context_->properties.limits;
    const std::string device = " of " + context_->info.device;
    if (std::uint32_t(desc.width) > limits.maxImageDimension2D ||
        std::uint32_t(desc.height) > limits.maxImageDimension2D)
        throw Error(what + ": " + describeSize(desc) + " exceeds maxImageDimension2D " +
                    std::to_string(limits.maxImageDimension2D) + device);
    if ((desc.usage & UsageRenderTarget) && (std::uint32_t(desc.width) > limits.maxFramebufferWidth ||
                                             std::uint32_t(desc.height) > limits.maxFramebufferHeight))
        throw Error(what + ": " + describeSize(desc) + " exceeds the largest framebuffer " +
                    std::to_string(limits.maxFramebufferWidth) + "x" + std::to_string(limits.maxFramebufferHeight) +
                    device);
}

MemoryProbe VulkanDriverImpl::memoryProbe() const {
    if (options_.memory) return options_.memory;
    if (context_->properties.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU) return hostMemoryAvailable;
    // A GPU: the largest device-local heap less what this backend holds (other processes' use
    // is not seen; the allocation's own VK_ERROR_OUT_OF_DEVICE_MEMORY covers that).
    return [this]() -> std::optional<AvailableMemory> {
        std::uint64_t heap = 0;
        for (std::uint32_t i = 0; i < context_->memory.memoryHeapCount; ++i)
            if (context_->memory.memoryHeaps[i].flags & VK_MEMORY_HEAP_DEVICE_LOCAL_BIT)
                heap = std::max(heap, std::uint64_t(context_->memory.memoryHeaps[i].size));
        if (heap == 0) return std::nullopt;
        return AvailableMemory{heap > heldBytes_ ? heap - heldBytes_ : 0,
                               "the device-local heap of " + context_->info.device + " less this backend's images"};
    };
}

void VulkanDriverImpl::destroyTexture(NativeId h) {
    const VulkanTexture t = textures_[h];
    textures_.remove(h);
    forgetFramebuffers(t.view);
    frames_->retire([this, t] { destroyTextureObjects(t); });
}

VulkanBuffer VulkanDriverImpl::makeBuffer(const BufferDesc& desc, const std::string& what) {
    const VkBufferUsageFlags usage =
        desc.kind == BufferKind::Index ? VK_BUFFER_USAGE_INDEX_BUFFER_BIT : VK_BUFFER_USAGE_VERTEX_BUFFER_BIT;
    checkFitsInMemory(desc.size, what + ": " + std::to_string(desc.size) + " bytes", memoryProbe());
    const MemoryBuffer m = createHostBuffer(*context_, desc.size, usage, what);
    ++counters_.buffersCreated;
    VulkanBuffer b;
    b.desc = desc;
    b.buffer = m.buffer;
    b.memory = m.memory;
    b.mapped = m.mapped;
    return b;
}

NativeId VulkanDriverImpl::createBuffer(const BufferDesc& desc, std::span<const std::byte> data,
                                        const std::string& what) {
    VulkanBuffer b = makeBuffer(desc, what);
    if (data.empty()) std::memset(b.mapped, 0, desc.size);
    else std::memcpy(b.mapped, data.data(), desc.size);
    return buffers_.add(std::move(b));
}

// A buffer a recorded or running submission still reads is renamed: the update goes to a new
// buffer holding the old contents, and the old one is destroyed once those submissions are done.
void VulkanDriverImpl::updateBuffer(NativeId handle, std::uint64_t offset, std::span<const std::byte> data) {
    VulkanBuffer& b = buffers_[handle];
    if (b.lastUse > frames_->completedSerial()) {
        // A spare of the same size and kind (one this buffer or another retired) when there is
        // one: a steady frame that updates a buffer each frame cycles through a few, creating none.
        const std::pair key{b.desc.size, b.desc.kind};
        MemoryBuffer renamed;
        auto spare = spareBuffers_.find(key);
        if (spare != spareBuffers_.end()) {
            renamed = spare->second;
            spareBuffers_.erase(spare);
        } else {
            const VulkanBuffer made = makeBuffer(b.desc, "buffer " + quotedName(b.desc.name));
            renamed = {made.buffer, made.memory, made.mapped};
        }
        std::memcpy(renamed.mapped, b.mapped, b.desc.size);
        const MemoryBuffer old{b.buffer, b.memory, b.mapped};
        frames_->retire([this, key, old] { spareBuffers_.emplace(key, old); });
        b.buffer = renamed.buffer;
        b.memory = renamed.memory;
        b.mapped = renamed.mapped;
        b.lastUse = 0;
    }
    std::memcpy(b.mapped + offset, data.data(), data.size());
}

void VulkanDriverImpl::destroyBuffer(NativeId h) {
    const VulkanBuffer& b = buffers_[h];
    const MemoryBuffer old{b.buffer, b.memory, b.mapped};
    buffers_.remove(h);
    frames_->retire([device = context_->device, old] { vk::destroyBuffer(device, old); });
}

std::shared_ptr<const VulkanProgram> VulkanDriverImpl::buildProgram(std::shared_ptr<const ProgramDesc> desc) {
    auto p = std::make_shared<VulkanProgram>();
    p->device = context_->device;
    p->block = uniformBlockLayout(desc->name, desc->gl);
    if (p->block.size > kUniformWindow)
        throw Error("program '" + desc->name + "': its uniform block is " + std::to_string(p->block.size) +
                    " bytes, the Vulkan backend binds at most " + std::to_string(kUniformWindow));
    const std::vector<std::uint32_t> vertex =
        compileSpirv(desc->name, Stage::Vertex, vertexSource(desc->vertexInput, desc->name, p->block));
    const VkDevice device = context_->device;
    auto module = [&](const std::vector<std::uint32_t>& code, VkShaderModule& out) {
        VkShaderModuleCreateInfo ci{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
        ci.codeSize = code.size() * 4;
        ci.pCode = code.data();
        check(vkCreateShaderModule(device, &ci, nullptr, &out), "program '" + desc->name + "': a shader module");
    };
    module(vertex, p->vertex);
    p->desc = desc;
    fragmentModule(*p, kMaxColorTargets);
    std::vector<VkDescriptorSetLayoutBinding> bindings;
    for (const TextureField& t : desc->gl.textures) {
        VkDescriptorSetLayoutBinding b{};
        b.binding = std::uint32_t(t.unit);
        b.descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
        b.descriptorCount = 1;
        b.stageFlags = VK_SHADER_STAGE_FRAGMENT_BIT;
        bindings.push_back(b);
    }
    VkDescriptorSetLayoutCreateInfo lci{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    lci.bindingCount = std::uint32_t(bindings.size());
    lci.pBindings = bindings.data();
    check(vkCreateDescriptorSetLayout(device, &lci, nullptr, &p->textureLayout),
          "program '" + desc->name + "': its texture set layout");
    const VkDescriptorSetLayout sets[] = {p->textureLayout, frames_->uniformLayout()};
    const VkPushConstantRange push{VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof(TailConstants)};
    VkPipelineLayoutCreateInfo pci{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    pci.setLayoutCount = 2;
    pci.pSetLayouts = sets;
    pci.pushConstantRangeCount = 1;
    pci.pPushConstantRanges = &push;
    check(vkCreatePipelineLayout(device, &pci, nullptr, &p->layout), "program '" + desc->name + "': its layout");
    return p;
}

VkShaderModule VulkanDriverImpl::fragmentModule(const VulkanProgram& p, int colorTargets) {
    VkShaderModule& m = p.fragments[std::size_t(colorTargets)];
    if (m) return m;
    const std::vector<std::uint32_t> code = compileSpirv(
        p.desc->name, Stage::Fragment, fragmentSource(p.desc->vertexInput, p.block, p.desc->gl.fragment, colorTargets));
    VkShaderModuleCreateInfo ci{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
    ci.codeSize = code.size() * 4;
    ci.pCode = code.data();
    check(vkCreateShaderModule(context_->device, &ci, nullptr, &m), "program '" + p.desc->name + "': a shader module");
    return m;
}

NativeId VulkanDriverImpl::createProgram(std::shared_ptr<const ProgramDesc> desc) {
    if (desc->gl.fragment.empty())
        throw Error("program " + quotedName(desc->name) + " has no GLSL for the Vulkan backend");
    return programs_.add(buildProgram(std::move(desc)));
}

NativeId VulkanDriverImpl::createStandardProgram(ProgramKind kind, ProgramDesc desc) {
    desc.gl.fragment = glsl::standardFragmentBody(kind);
    return programs_.add(buildProgram(std::make_shared<const ProgramDesc>(std::move(desc))));
}

void VulkanDriverImpl::destroyProgram(NativeId h) {
    std::shared_ptr<const VulkanProgram> p = programs_[h];
    programs_.remove(h);
    frames_->retire([p] {});  // its pipelines may be in flight: released after them
}

void VulkanDriverImpl::notePipeline(const PipelineDesc& desc, ResolvedPipeline& resolved) {
    if (!resolved.info.exact)
        log::warn("Vulkan pipeline ", quotedName(desc.name), ": inexact emulation: ", resolved.info.note);
}

}  // namespace engine::render::vk
