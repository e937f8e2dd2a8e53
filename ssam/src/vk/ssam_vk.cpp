// SPDX-License-Identifier: MIT
// ssam::vk's public API: the objects made at initialize(), the frame recorded into the host's
// command buffer (way a), and the boundary where every internal Failure becomes a Status + message.
#include "ssam/vk/ssam_vk.hpp"

#include <cmath>
#include <cstring>
#include <new>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ssam/core/settings.hpp"
#include "../core/host_passes_impl.hpp"
#include "impl.hpp"

namespace ssam::vk {

using detail::check;
using detail::Constants;
using detail::kFrameBlockSize;
using detail::Failure;

namespace {

// The knobs by the core's rules (ssam::settingsError), as every SSAM checks them.
void validate(const Settings& s) {
    if (const std::string error = ssam::settingsError(s); !error.empty())
        throw Failure(Status::InvalidArgument, "ssam::vk: " + error);
}

// The instance tint's formats: the four-channel ones the shader reads as float (not UINT / SINT)
// that every Vulkan device supports for vertex buffers (the specification's "Required Format
// Support" tables), so no device query is needed to accept one.
bool isTintFormat(VkFormat f) {
    switch (f) {
        case VK_FORMAT_R32G32B32A32_SFLOAT:
        case VK_FORMAT_R16G16B16A16_SFLOAT:
        case VK_FORMAT_R16G16B16A16_UNORM:
        case VK_FORMAT_R16G16B16A16_SNORM:
        case VK_FORMAT_R8G8B8A8_UNORM:
        case VK_FORMAT_R8G8B8A8_SNORM:
        case VK_FORMAT_B8G8R8A8_UNORM:
        case VK_FORMAT_A8B8G8R8_UNORM_PACK32:
        case VK_FORMAT_A8B8G8R8_SNORM_PACK32:
        case VK_FORMAT_A2B10G10R10_UNORM_PACK32: return true;
        default: return false;
    }
}

// Where the built-in programs read the host's vertex buffers: bindings that exist, a position, a
// tint of a format Vulkan reads as float.
void validate(const VertexLayout& v) {
    if (v.bindingCount == 0 || v.bindingCount > VertexLayout::kMaxBindings)
        throw Failure(Status::InvalidArgument,
                      "ssam::vk: vertexLayout.bindingCount " + std::to_string(v.bindingCount) + " is not 1 to 4");
    if (v.position.format == VK_FORMAT_UNDEFINED)
        throw Failure(Status::InvalidArgument, "ssam::vk: vertexLayout.position has no format");
    if (v.constantsBinding >= 16)
        throw Failure(Status::InvalidArgument, "ssam::vk: vertexLayout.constantsBinding " +
                                                   std::to_string(v.constantsBinding) +
                                                   " is past 15 (Vulkan guarantees 16 vertex bindings)");
    const auto known = [&](const VertexAttribute& a) {
        if (a.format == VK_FORMAT_UNDEFINED) return true;
        for (std::uint32_t i = 0; i < v.bindingCount; ++i)
            if (v.bindings[i].binding == a.binding) return true;
        return false;
    };
    const std::pair<const char*, const VertexAttribute*> attributes[] = {{"position", &v.position},
                                                                         {"normal", &v.normal},
                                                                         {"uv", &v.uv},
                                                                         {"color", &v.color},
                                                                         {"instanceModel", &v.instanceModel},
                                                                         {"instanceTint", &v.instanceTint}};
    for (const auto& [name, a] : attributes)
        if (!known(*a))
            throw Failure(Status::InvalidArgument, std::string("ssam::vk: vertexLayout.") + name + " reads binding " +
                                                       std::to_string(a->binding) +
                                                       ", which vertexLayout.bindings does not describe");
    if (v.instanceTint.format != VK_FORMAT_UNDEFINED && !isTintFormat(v.instanceTint.format))
        throw Failure(Status::InvalidArgument,
                      "ssam::vk: vertexLayout.instanceTint.format " + detail::formatName(v.instanceTint.format) +
                          " is not a four-channel float, UNORM or SNORM format every device reads from vertex "
                          "buffers (ssam_vk.hpp's VertexLayout lists them)");
    for (std::uint32_t i = 0; i < v.bindingCount; ++i)
        if (v.bindings[i].binding == v.constantsBinding)
            throw Failure(Status::InvalidArgument, "ssam::vk: vertexLayout.bindings[" + std::to_string(i) +
                                                       "] is the constants binding " +
                                                       std::to_string(v.constantsBinding));
}

// The device features a setting needs, against those the host enabled (DeviceDesc).
void checkFeatures(const Settings& s, const DeviceDesc& d) {
    if (s.maskPrecision == MaskPrecision::Rg16f && !d.independentBlend)
        throw Failure(Status::UnsupportedFeature,
                      "ssam::vk settings: maskPrecision Rg16f needs the host's independentBlend feature (its two mask "
                      "attachments blend MAX and ADD; VkPhysicalDeviceFeatures::independentBlend enabled at "
                      "vkCreateDevice, then DeviceDesc::independentBlend = true)");
}

bool sameLayout(const VertexLayout& a, const VertexLayout& b) { return std::memcmp(&a, &b, sizeof(VertexLayout)) == 0; }

}  // namespace

void ScreenSpaceAlphaMaskVk::Impl::initialize(const DeviceDesc& desc, const Settings& wanted,
                                              const VertexLayout& wantedLayout) {
    if (!desc.instance || !desc.physicalDevice || !desc.device || !desc.getInstanceProcAddr)
        throw Failure(Status::InvalidArgument,
                      "ssam::vk: DeviceDesc needs instance, physicalDevice, device and getInstanceProcAddr");
    if (desc.apiVersion < VK_API_VERSION_1_0)
        throw Failure(Status::InvalidArgument, "ssam::vk: DeviceDesc::apiVersion is not a Vulkan version");
    if ((desc.memory.allocate != nullptr) != (desc.memory.release != nullptr))
        throw Failure(Status::InvalidArgument, "ssam::vk: DeviceMemoryCallbacks needs both allocate and release");
    validate(wanted);
    validate(wantedLayout);
    checkFeatures(wanted, desc);
    if (desc.renderingPath != RenderingPath::RenderPass && desc.renderingPath != RenderingPath::DynamicRendering)
        throw Failure(Status::InvalidArgument, "ssam::vk: DeviceDesc::renderingPath is not a RenderingPath");
    if (desc.renderingPath == RenderingPath::DynamicRendering && !desc.dynamicRendering)
        throw Failure(Status::UnsupportedFeature,
                      "ssam::vk: RenderingPath::DynamicRendering needs the host's dynamicRendering feature "
                      "(DeviceDesc::dynamicRendering: Vulkan 1.3's, or VK_KHR_dynamic_rendering's)");
    releaseObjects();
    detail::loadFunctions(vk, desc);
    device = desc;
    settings = wanted;
    vertexLayout = wantedLayout;
    initialized = true;  // from here release() destroys what exists if a step fails
    try {
        memory.reset(vk, desc.physicalDevice, desc.memory);
        shared.create(vk);
        constants = detail::createBuffer(
            vk, memory, sizeof(Constants),
            VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT | VK_BUFFER_USAGE_VERTEX_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
            "SSAM's constants");
        white = detail::createImage(vk, memory, VK_FORMAT_R8G8B8A8_UNORM, 1, 1,
                                    VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT, "the white texel");
        const VkDescriptorPoolSize sizes[] = {{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1},
                                              {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1}};
        VkDescriptorPoolCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
        info.maxSets = 2;
        info.poolSizeCount = 2;
        info.pPoolSizes = sizes;
        check(vk.CreateDescriptorPool(vk.device, &info, vk.allocator, &staticPool), "vkCreateDescriptorPool");
        const VkDescriptorSetLayout layouts[] = {shared.frameSetLayout, shared.textureSetLayout};
        VkDescriptorSetAllocateInfo allocate{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
        allocate.descriptorPool = staticPool;
        allocate.descriptorSetCount = 2;
        allocate.pSetLayouts = layouts;
        VkDescriptorSet sets[2];
        check(vk.AllocateDescriptorSets(vk.device, &allocate, sets), "vkAllocateDescriptorSets");
        frameSet = sets[0], whiteSet = sets[1];
        const VkDescriptorBufferInfo block{constants.buffer, 0, kFrameBlockSize};
        const VkDescriptorImageInfo texel{shared.linearSampler, white.view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
        VkWriteDescriptorSet writes[2] = {{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET},
                                          {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET}};
        writes[0].dstSet = frameSet;
        writes[0].descriptorCount = 1;
        writes[0].descriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
        writes[0].pBufferInfo = &block;
        writes[1].dstSet = whiteSet;
        writes[1].descriptorCount = 1;
        writes[1].descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
        writes[1].pImageInfo = &texel;
        vk.UpdateDescriptorSets(vk.device, 2, writes, 0, nullptr);
    } catch (...) {
        releaseObjects();
        throw;
    }
    VkPhysicalDeviceProperties properties;
    vk.GetPhysicalDeviceProperties(desc.physicalDevice, &properties);
    maxFramebufferWidth = properties.limits.maxFramebufferWidth;
    maxFramebufferHeight = properties.limits.maxFramebufferHeight;
    maxImageDimension2D = properties.limits.maxImageDimension2D;
    message(Severity::Info, std::string("ssam::vk initialised on ") + properties.deviceName + " (Vulkan " +
                                std::to_string(VK_API_VERSION_MAJOR(desc.apiVersion)) + "." +
                                std::to_string(VK_API_VERSION_MINOR(desc.apiVersion)) + ")");
}

void ScreenSpaceAlphaMaskVk::Impl::releaseObjects() noexcept {
    if (!initialized) return;
    abandonFrame();
    frameFramebuffers.destroyAll([this](const detail::FrameFramebuffers& fb) { detail::destroyFramebuffers(vk, fb); });
    retired.destroyAll();
    lastFrameIndex.reset();
    lastFramesCompleted = 0;
    warnedFramesNotCompleting = false;
    for (const CompatiblePass& c : compatiblePasses) vk.DestroyRenderPass(vk.device, c.pass, vk.allocator);
    compatiblePasses.clear();
    if (generation) generation->destroy(vk, memory);
    generation.reset();
    for (VkDescriptorPool p : texturePools) vk.DestroyDescriptorPool(vk.device, p, vk.allocator);
    texturePools.clear();
    textures.clear();
    textureSetPools.clear();
    if (staticPool) vk.DestroyDescriptorPool(vk.device, staticPool, vk.allocator);
    staticPool = VK_NULL_HANDLE;
    frameSet = whiteSet = VK_NULL_HANDLE;
    detail::destroy(vk, memory, white);
    detail::destroy(vk, memory, constants);
    shared.destroy(vk);
    initialized = false;
}

TextureId ScreenSpaceAlphaMaskVk::Impl::createTexture(VkImageView view, VkSampler sampler) {
    expectInitialized("createTexture");
    if (!view) throw Failure(Status::InvalidArgument, "ssam::vk: createTexture() with view VK_NULL_HANDLE");
    VkDescriptorSet set = VK_NULL_HANDLE;
    VkDescriptorSetAllocateInfo allocate{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    allocate.descriptorSetCount = 1;
    allocate.pSetLayouts = &shared.textureSetLayout;
    for (VkDescriptorPool pool : texturePools) {
        allocate.descriptorPool = pool;
        if (vk.AllocateDescriptorSets(vk.device, &allocate, &set) == VK_SUCCESS) break;
        set = VK_NULL_HANDLE;
    }
    if (!set) {  // every pool full: one more
        const VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, kTexturesPerPool};
        VkDescriptorPoolCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
        info.flags = VK_DESCRIPTOR_POOL_CREATE_FREE_DESCRIPTOR_SET_BIT;
        info.maxSets = kTexturesPerPool;
        info.poolSizeCount = 1;
        info.pPoolSizes = &size;
        VkDescriptorPool pool = VK_NULL_HANDLE;
        check(vk.CreateDescriptorPool(vk.device, &info, vk.allocator, &pool), "vkCreateDescriptorPool");
        texturePools.push_back(pool);
        allocate.descriptorPool = pool;
        check(vk.AllocateDescriptorSets(vk.device, &allocate, &set), "vkAllocateDescriptorSets");
    }
    const VkDescriptorImageInfo image{sampler ? sampler : shared.linearSampler, view,
                                      VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    write.dstSet = set;
    write.descriptorCount = 1;
    write.descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    write.pImageInfo = &image;
    vk.UpdateDescriptorSets(vk.device, 1, &write, 0, nullptr);
    textures.push_back(set);
    textureSetPools.push_back(allocate.descriptorPool);
    return TextureId(textures.size());
}

void ScreenSpaceAlphaMaskVk::Impl::destroyTexture(TextureId id, std::uint64_t lastFrame) {
    expectInitialized("destroyTexture");
    if (id == 0 || id > textures.size() || !textures[id - 1])
        throw Failure(Status::InvalidArgument, "ssam::vk: destroyTexture(" + std::to_string(id) + "): no such texture");
    const VkDescriptorSet set = textures[id - 1];
    const VkDescriptorPool pool = textureSetPools[id - 1];
    textures[id - 1] = VK_NULL_HANDLE;
    retired.add(lastFrame, [this, set, pool] { vk.FreeDescriptorSets(vk.device, pool, 1, &set); });
}

// ---- Public calls --------------------------------------------------------------------------

ScreenSpaceAlphaMaskVk::ScreenSpaceAlphaMaskVk() noexcept : impl_(new (std::nothrow) Impl) {}
ScreenSpaceAlphaMaskVk::~ScreenSpaceAlphaMaskVk() { release(); }
ScreenSpaceAlphaMaskVk::ScreenSpaceAlphaMaskVk(ScreenSpaceAlphaMaskVk&&) noexcept = default;
ScreenSpaceAlphaMaskVk& ScreenSpaceAlphaMaskVk::operator=(ScreenSpaceAlphaMaskVk&& other) noexcept {
    if (this != &other) {
        release();
        impl_ = std::move(other.impl_);
    }
    return *this;
}

Status ScreenSpaceAlphaMaskVk::initialize(const DeviceDesc& device, const Settings& settings,
                                          const VertexLayout& vertexLayout) noexcept {
    if (!impl_) return Status::InvalidCall;
    return impl_->run([&] { impl_->initialize(device, settings, vertexLayout); });
}

void ScreenSpaceAlphaMaskVk::release() noexcept {
    if (impl_) impl_->releaseObjects();
}

namespace {

// A call that changes what every pass of a frame is drawn with: `change(impl)`, refused
// (InvalidCall) on a moved-from object or inside a frame.
template <class Change>
Status changeOutsideFrame(ScreenSpaceAlphaMaskVk::Impl* impl, const char* call, Change&& change) noexcept {
    if (!impl) return Status::InvalidCall;
    return impl->run([&] {
        core::expectNoFrame("ssam::vk", impl->phase, call);
        change(*impl);
    });
}

}  // namespace

Status ScreenSpaceAlphaMaskVk::setSettings(const Settings& settings) noexcept {
    return changeOutsideFrame(impl_.get(), "setSettings", [&](Impl& s) {
        validate(settings);
        if (s.initialized) checkFeatures(settings, s.device);
        if (settings.depthTest != s.settings.depthTest) ++s.settingsVersion;  // the pipelines' depth test
        // What PipelineState holds (way b): the depth test and the mask's format.
        if (settings.depthTest != s.settings.depthTest || settings.maskPrecision != s.settings.maskPrecision)
            ++s.pipelineStateVersion;
        s.settings = settings;
    });
}

Status ScreenSpaceAlphaMaskVk::setVertexLayout(const VertexLayout& vertexLayout) noexcept {
    return changeOutsideFrame(impl_.get(), "setVertexLayout", [&](Impl& s) {
        validate(vertexLayout);
        if (!sameLayout(vertexLayout, s.vertexLayout)) ++s.settingsVersion;  // new pipelines
        s.vertexLayout = vertexLayout;
    });
}

const VertexLayout& ScreenSpaceAlphaMaskVk::vertexLayout() const noexcept {
    static const VertexLayout defaults;
    return impl_ ? impl_->vertexLayout : defaults;
}

Status ScreenSpaceAlphaMaskVk::createTexture(VkImageView view, VkSampler sampler, TextureId* id) noexcept {
    if (!impl_) return Status::InvalidCall;
    if (id) *id = 0;
    return impl_->run(
        [&] {
            // Checked before anything is made: a texture without its id could never be bound or destroyed.
            if (!id) throw Failure(Status::InvalidArgument, "ssam::vk: createTexture() with id null");
            *id = impl_->createTexture(view, sampler);
        },
        false);
}

Status ScreenSpaceAlphaMaskVk::destroyTexture(TextureId id, std::uint64_t lastFrameIndex) noexcept {
    if (!impl_) return Status::InvalidCall;
    return impl_->run([&] { impl_->destroyTexture(id, lastFrameIndex); }, false);
}

Status ScreenSpaceAlphaMaskVk::pipelineState(FoliagePass pass, VkFormat colorFormat, VkFormat depthFormat,
                                             PipelineState* state) const noexcept {
    if (!impl_) return Status::InvalidCall;
    if (!state) return impl_->fail(Status::InvalidArgument, "ssam::vk: pipelineState() without a PipelineState");
    if (pass != FoliagePass::Mask && pass != FoliagePass::Color)
        return impl_->fail(Status::InvalidArgument, "ssam::vk: pipelineState() of a pass that is not a FoliagePass");
    return impl_->run([&] { *state = impl_->pipelineStateFor(pass, colorFormat, depthFormat); }, false);
}

std::uint64_t ScreenSpaceAlphaMaskVk::pipelineStateVersion() const noexcept {
    return impl_ ? impl_->pipelineStateVersion : 0;
}

ScreenSpaceAlphaMaskVk::Intermediates ScreenSpaceAlphaMaskVk::intermediates() const noexcept {
    if (!impl_ || !impl_->generation) return {};
    const detail::Generation& g = *impl_->generation;
    return {g.mask.image, g.maskAdd.image, g.foliage.image};
}

}  // namespace ssam::vk

// The calls ssam::vk shares with every host API, over Impl (host_passes_impl.hpp).
template class ssam::HostPasses<ssam::vk::ScreenSpaceAlphaMaskVk, ssam::vk::FrameDesc, ssam::vk::FoliageProgram,
                                ssam::vk::PassInfo>;
