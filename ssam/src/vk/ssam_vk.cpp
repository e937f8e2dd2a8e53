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

#include "../knob_rules.hpp"
#include "dynamic_rendering.hpp"
#include "failure.hpp"
#include "pipelines.hpp"
#include "resources.hpp"
#include "vk_functions.hpp"

namespace ssam::vk {

using detail::check;
using detail::Failure;

const char* statusName(Status status) noexcept {
    switch (status) {
        case Status::Ok: return "ok";
        case Status::InvalidArgument: return "invalid argument";
        case Status::InvalidCall: return "invalid call";
        case Status::MissingEntryPoint: return "missing entry point";
        case Status::UnsupportedFeature: return "unsupported feature";
        case Status::DeviceError: return "device error";
        case Status::CallbackFailed: return "callback failed";
        case Status::OutOfMemory: return "out of memory";
        case Status::Internal: return "internal error";
    }
    return "unknown status";
}

const char* severityName(Severity severity) noexcept {
    switch (severity) {
        case Severity::Info: return "info";
        case Severity::Warning: return "warning";
        case Severity::Error: return "error";
    }
    return "unknown severity";
}

const char* foliagePassName(FoliagePass pass) noexcept { return pass == FoliagePass::Mask ? "mask" : "colour"; }

namespace detail {

// What FoliageProgram records through: the frame's command buffer and the texture sets.
struct Recorder {
    const VkFunctions* vk = nullptr;
    VkCommandBuffer commandBuffer = VK_NULL_HANDLE;
    VkPipelineLayout layout = VK_NULL_HANDLE;
    const std::vector<VkDescriptorSet>* textures = nullptr;  // TextureId - 1
    VkDescriptorSet white = VK_NULL_HANDLE;                  // TextureId 0

    void push(std::uint32_t offset, std::uint32_t size, const void* data) const {
        vk->CmdPushConstants(commandBuffer, layout, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, offset,
                             size, data);
    }
    void bindTexture(TextureId id) const {
        VkDescriptorSet set = white;
        if (id != 0 && id <= textures->size() && (*textures)[id - 1] != VK_NULL_HANDLE) set = (*textures)[id - 1];
        else id = 0;
        vk->CmdBindDescriptorSets(commandBuffer, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, 1, 1, &set, 0, nullptr);
        const std::uint32_t has = id != 0 ? 1u : 0u;
        push(80, 4, &has);
    }
};

}  // namespace detail

void FoliageProgram::setModel(const float columnMajor[16]) const noexcept {
    if (recorder && columnMajor) recorder->push(0, 64, columnMajor);
}
void FoliageProgram::setBaseColorFactor(float r, float g, float b, float a) const noexcept {
    const float factor[4] = {r, g, b, a};
    if (recorder) recorder->push(64, 16, factor);
}
void FoliageProgram::bindBaseColorTexture(TextureId texture) const noexcept {
    if (recorder) recorder->bindTexture(texture);
}

namespace {

// SSAM's constants buffer: the frame's uniform block (std140, glsl_variants.cpp's SsamFrame) at 0
// and, at kVertexConstants, the values of the vertex attributes a host does not give
// (pipelines.cpp's vertexInput reads them there with stride 0). Rewritten by each frame with
// vkCmdUpdateBuffer, so frames in flight never share a value the host changed.
struct Constants {
    float viewProj[16];
    float towardLight[4], lightColor[4], ambient[4];
    float alphaReference, pad0[3];
    float pad1[32];           // to kVertexConstants (a multiple of minUniformBufferOffsetAlignment's 256 maximum)
    float normal[4];          // (0, 0, 1)
    float uv[4];              // (0, 0)
    float color[4];           // (1, 1, 1, 1)
    float instanceModel[16];  // identity
};
constexpr std::uint32_t kFrameBlockSize = 128;
static_assert(sizeof(Constants) == 256 + 28 * 4, "Constants' layout is pipelines.cpp's and the shaders'");

bool isColorFormat(VkFormat f) {
    return f == VK_FORMAT_R8G8B8A8_UNORM || f == VK_FORMAT_R8G8B8A8_SRGB || f == VK_FORMAT_B8G8R8A8_UNORM ||
           f == VK_FORMAT_B8G8R8A8_SRGB || f == VK_FORMAT_R16G16B16A16_SFLOAT || f == VK_FORMAT_R32G32B32A32_SFLOAT;
}
bool isDepthFormat(VkFormat f) {
    return f == VK_FORMAT_D16_UNORM || f == VK_FORMAT_X8_D24_UNORM_PACK32 || f == VK_FORMAT_D32_SFLOAT ||
           f == VK_FORMAT_D24_UNORM_S8_UINT || f == VK_FORMAT_D32_SFLOAT_S8_UINT;
}

void validate(const Settings& s) {
    const auto precision = static_cast<int>(s.maskPrecision);
    const auto depth = static_cast<int>(s.depthTest);
    if (precision < 0 || precision > static_cast<int>(MaskPrecision::Rgba16f))
        throw Failure(Status::InvalidArgument,
                      "ssam::vk settings: maskPrecision " + std::to_string(precision) + " is not a MaskPrecision");
    if (depth < 0 || depth > static_cast<int>(DepthTest::GreaterEqual))
        throw Failure(Status::InvalidArgument,
                      "ssam::vk settings: depthTest " + std::to_string(depth) + " is not a DepthTest");
    if (const std::string error = ssam::detail::knobError(s.maskLerp, s.colorAlphaReference, s.foliageClearColor);
        !error.empty())
        throw Failure(Status::InvalidArgument, "ssam::vk settings: " + error);
    const VertexLayout& v = s.vertexLayout;
    if (v.bindingCount == 0 || v.bindingCount > VertexLayout::kMaxBindings)
        throw Failure(Status::InvalidArgument, "ssam::vk settings: vertexLayout.bindingCount " +
                                                   std::to_string(v.bindingCount) + " is not 1 to 4");
    if (v.position.format == VK_FORMAT_UNDEFINED)
        throw Failure(Status::InvalidArgument, "ssam::vk settings: vertexLayout.position has no format");
    if (v.constantsBinding >= 16)
        throw Failure(Status::InvalidArgument, "ssam::vk settings: vertexLayout.constantsBinding " +
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
                                                                         {"instanceModel", &v.instanceModel}};
    for (const auto& [name, a] : attributes)
        if (!known(*a))
            throw Failure(Status::InvalidArgument, std::string("ssam::vk settings: vertexLayout.") + name +
                                                       " reads binding " + std::to_string(a->binding) +
                                                       ", which vertexLayout.bindings does not describe");
    for (std::uint32_t i = 0; i < v.bindingCount; ++i)
        if (v.bindings[i].binding == v.constantsBinding)
            throw Failure(Status::InvalidArgument, "ssam::vk settings: vertexLayout.bindings[" + std::to_string(i) +
                                                       "] is the constants binding " +
                                                       std::to_string(v.constantsBinding));
}

bool samePipelines(const Settings& a, const Settings& b) {
    return a.depthTest == b.depthTest && std::memcmp(&a.vertexLayout, &b.vertexLayout, sizeof(VertexLayout)) == 0;
}

}  // namespace

struct ScreenSpaceAlphaMaskVk::Impl {
    detail::VkFunctions vk;
    DeviceDesc device;
    bool initialized = false;
    Settings settings;
    std::uint64_t settingsVersion = 0;
    MessageCallback onMessage = nullptr;
    void* messageUser = nullptr;
    std::string lastMessage;

    detail::MemorySource memory;
    detail::SharedObjects shared;
    detail::Buffer constants;
    detail::Image white;  // the texture of "no texture": one texel of (1,1,1,1), cleared every frame
    VkDescriptorPool staticPool = VK_NULL_HANDLE;
    VkDescriptorSet frameSet = VK_NULL_HANDLE, whiteSet = VK_NULL_HANDLE;
    std::vector<VkDescriptorPool> texturePools;  // kTexturesPerPool sets each
    std::vector<VkDescriptorSet> textures;       // TextureId - 1; VK_NULL_HANDLE when destroyed
    std::vector<VkDescriptorPool> textureSetPools;
    std::optional<detail::Generation> generation;
    detail::Retired retired;
    static constexpr std::uint32_t kTexturesPerPool = 64;

    void message(Severity severity, const std::string& text) noexcept {
        if (!onMessage) return;
        try {
            onMessage(messageUser, severity, text.c_str());
        } catch (...) {  // the host's callback must not unwind through SSAM
        }
    }
    Status fail(Status status, const char* text) noexcept {
        try {
            lastMessage = text;
        } catch (...) {
            lastMessage.clear();
        }
        message(Severity::Error, text);
        return status;
    }
    template <class Body>
    Status run(Body&& body) noexcept {
        try {
            body();
            return Status::Ok;
        } catch (const Failure& e) {
            return fail(e.status, e.what());
        } catch (const std::bad_alloc&) {
            return fail(Status::OutOfMemory, "ssam::vk: out of memory");
        } catch (const std::exception& e) {
            return fail(Status::Internal, (std::string("ssam::vk: unexpected error: ") + e.what()).c_str());
        } catch (...) {
            return fail(Status::Internal, "ssam::vk: unexpected error");
        }
    }
    void expectInitialized(const char* call) const {
        if (!initialized) throw Failure(Status::InvalidCall, std::string("ssam::vk: ") + call + " before initialize()");
    }

    // ---- Objects made once ----------------------------------------------------------------

    void initialize(const DeviceDesc& desc, const Settings& wanted) {
        if (!desc.instance || !desc.physicalDevice || !desc.device || !desc.getInstanceProcAddr)
            throw Failure(Status::InvalidArgument,
                          "ssam::vk: DeviceDesc needs instance, physicalDevice, device and getInstanceProcAddr");
        if (desc.apiVersion < VK_API_VERSION_1_0)
            throw Failure(Status::InvalidArgument, "ssam::vk: DeviceDesc::apiVersion is not a Vulkan version");
        if ((desc.memory.allocate != nullptr) != (desc.memory.release != nullptr))
            throw Failure(Status::InvalidArgument, "ssam::vk: DeviceMemoryCallbacks needs both allocate and release");
        validate(wanted);
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
        initialized = true;  // from here release() destroys what exists if a step fails
        try {
            memory.reset(vk, desc.physicalDevice, desc.memory);
            shared.create(vk);
            constants = detail::createBuffer(vk, memory, sizeof(Constants),
                                             VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT | VK_BUFFER_USAGE_VERTEX_BUFFER_BIT |
                                                 VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                             "SSAM's constants");
            white =
                detail::createImage(vk, memory, VK_FORMAT_R8G8B8A8_UNORM, 1, 1,
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
            const VkDescriptorImageInfo texel{shared.linearSampler, white.view,
                                              VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
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
        message(Severity::Info, std::string("ssam::vk initialised on ") + properties.deviceName + " (Vulkan " +
                                    std::to_string(VK_API_VERSION_MAJOR(desc.apiVersion)) + "." +
                                    std::to_string(VK_API_VERSION_MINOR(desc.apiVersion)) + ")");
    }

    void releaseObjects() noexcept {
        if (!initialized) return;
        retired.destroyAll();
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

    // ---- Host textures ------------------------------------------------------------------

    TextureId createTexture(VkImageView view, VkSampler sampler) {
        expectInitialized("createTexture");
        if (!view) throw Failure(Status::InvalidArgument, "ssam::vk: createTexture without an image view");
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

    void destroyTexture(TextureId id, std::uint64_t lastFrame) {
        expectInitialized("destroyTexture");
        if (id == 0 || id > textures.size() || !textures[id - 1])
            throw Failure(Status::InvalidArgument,
                          "ssam::vk: destroyTexture(" + std::to_string(id) + "): no such texture");
        const VkDescriptorSet set = textures[id - 1];
        const VkDescriptorPool pool = textureSetPools[id - 1];
        textures[id - 1] = VK_NULL_HANDLE;
        retired.add(lastFrame, [this, set, pool] { vk.FreeDescriptorSets(vk.device, pool, 1, &set); });
    }

    // ---- The frame ------------------------------------------------------------------------

    VkFormat maskFormat() const {
        return settings.maskPrecision == MaskPrecision::Rgba16f ? VK_FORMAT_R16G16B16A16_SFLOAT
                                                                : VK_FORMAT_R8G8B8A8_UNORM;
    }

    void checkFormat(VkFormat format, VkFormatFeatureFlags needed, const char* what) const {
        VkFormatProperties p;
        vk.GetPhysicalDeviceFormatProperties(device.physicalDevice, format, &p);
        if ((p.optimalTilingFeatures & needed) != needed)
            throw Failure(Status::UnsupportedFeature, std::string("ssam::vk: this device cannot use format ") +
                                                          std::to_string(int(format)) + " as " + what);
    }

    void checkFrame(const FrameDesc& f) const {
        if (!f.commandBuffer) throw Failure(Status::InvalidArgument, "ssam::vk: FrameDesc::commandBuffer is null");
        if (!f.colorView || !f.depthView)
            throw Failure(Status::InvalidArgument, "ssam::vk: FrameDesc needs colorView and depthView");
        if (f.width == 0 || f.height == 0)
            throw Failure(Status::InvalidArgument, "ssam::vk: frame size " + std::to_string(f.width) + "x" +
                                                       std::to_string(f.height) + " is not positive");
        if (!isColorFormat(f.colorFormat))
            throw Failure(Status::InvalidArgument,
                          "ssam::vk: colorFormat " + std::to_string(int(f.colorFormat)) +
                              " is not R8G8B8A8 / B8G8R8A8 UNORM or SRGB, R16G16B16A16_SFLOAT or R32G32B32A32_SFLOAT");
        if (!isDepthFormat(f.depthFormat))
            throw Failure(Status::InvalidArgument, "ssam::vk: depthFormat " + std::to_string(int(f.depthFormat)) +
                                                       " is not a depth format SSAM takes (ssam_vk.hpp)");
        if (f.framesCompleted > f.frameIndex)
            throw Failure(Status::InvalidArgument, "ssam::vk: framesCompleted " + std::to_string(f.framesCompleted) +
                                                       " is past frameIndex " + std::to_string(f.frameIndex));
    }

    bool dynamic() const { return device.renderingPath == RenderingPath::DynamicRendering; }

    const detail::Generation& generationFor(const FrameDesc& f) {
        const detail::GenerationKey key{f.colorFormat, f.depthFormat, maskFormat(), f.width, f.height, settingsVersion};
        if (generation && generation->key == key) return *generation;
        if (!generation || generation->key.colorFormat != key.colorFormat)
            checkFormat(key.colorFormat,
                        VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BLEND_BIT | VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT,
                        "a blended, sampled colour target");
        checkFormat(key.maskFormat, VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BLEND_BIT | VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT,
                    "the mask");
        detail::Generation next;
        next.create(vk, memory, shared, key, settings, dynamic());  // destroys what it made if it fails
        if (generation) {
            auto old = std::make_shared<detail::Generation>(std::move(*generation));
            retired.add(old->lastUsedFrame, [this, old] { old->destroy(vk, memory); });
        }
        generation = std::move(next);
        return *generation;
    }

    void updateConstants(const FrameDesc& f, VkCommandBuffer cb) {
        Constants c{};
        std::memcpy(c.viewProj, f.viewProj, sizeof c.viewProj);
        const Light& light = f.light;
        const float length =
            std::sqrt(light.towardLight[0] * light.towardLight[0] + light.towardLight[1] * light.towardLight[1] +
                      light.towardLight[2] * light.towardLight[2]);
        for (int i = 0; i < 3; ++i) {
            c.towardLight[i] = length > 0.0f && std::isfinite(length) ? light.towardLight[i] / length : 0.0f;
            c.lightColor[i] = light.color[i];
            c.ambient[i] = light.ambient[i];
        }
        c.alphaReference = settings.colorAlphaReference;
        c.normal[2] = 1.0f;
        for (float& v : c.color) v = 1.0f;
        for (int i = 0; i < 4; ++i) c.instanceModel[i * 5] = 1.0f;
        // The previous frame's reads (vertex input, uniforms, the white texel) before these writes
        // (an execution dependency is enough for a write after read), then the writes before this
        // frame's reads.
        VkBufferMemoryBarrier buffer{VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER};
        buffer.srcQueueFamilyIndex = buffer.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        buffer.buffer = constants.buffer;
        buffer.size = VK_WHOLE_SIZE;
        buffer.dstAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
        VkImageMemoryBarrier image{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
        image.srcQueueFamilyIndex = image.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        image.image = white.image;
        image.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
        image.oldLayout = VK_IMAGE_LAYOUT_UNDEFINED;
        image.newLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
        image.dstAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
        constexpr VkPipelineStageFlags kReaders = VK_PIPELINE_STAGE_VERTEX_INPUT_BIT |
                                                  VK_PIPELINE_STAGE_VERTEX_SHADER_BIT |
                                                  VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT;
        vk.CmdPipelineBarrier(cb, kReaders, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0, nullptr, 1, &buffer, 1, &image);
        vk.CmdUpdateBuffer(cb, constants.buffer, 0, sizeof c, &c);
        const VkClearColorValue one{{1.0f, 1.0f, 1.0f, 1.0f}};
        vk.CmdClearColorImage(cb, white.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &one, 1, &image.subresourceRange);
        buffer.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
        buffer.dstAccessMask = VK_ACCESS_VERTEX_ATTRIBUTE_READ_BIT | VK_ACCESS_UNIFORM_READ_BIT;
        image.oldLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
        image.newLayout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
        image.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
        image.dstAccessMask = VK_ACCESS_SHADER_READ_BIT;
        vk.CmdPipelineBarrier(cb, VK_PIPELINE_STAGE_TRANSFER_BIT, kReaders, 0, 0, nullptr, 1, &buffer, 1, &image);
    }

    // A pass begun on either path (RenderingPath), its pipeline bound, viewport and scissor the frame.
    void beginPass(const FrameDesc& f, const detail::Generation& g, const detail::FrameFramebuffers* fb,
                   detail::PassKind pass, const VkClearValue* clear, VkPipeline pipeline) {
        const VkCommandBuffer cb = f.commandBuffer;
        if (dynamic()) {
            detail::beginDynamicPass(vk, cb, pass, g, {f.colorView, f.depthView, f.depthFormat, f.width, f.height},
                                     clear);
        } else {
            VkRenderPassBeginInfo begin{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
            begin.renderPass = pass == detail::PassKind::Mask    ? g.maskPass
                               : pass == detail::PassKind::Color ? g.colorPass
                                                                 : g.compositePass;
            begin.framebuffer = pass == detail::PassKind::Mask    ? fb->mask
                                : pass == detail::PassKind::Color ? fb->color
                                                                  : fb->composite;
            begin.renderArea = {{0, 0}, {f.width, f.height}};
            begin.clearValueCount = clear ? 1 : 0;
            begin.pClearValues = clear;
            vk.CmdBeginRenderPass(cb, &begin, VK_SUBPASS_CONTENTS_INLINE);
        }
        vk.CmdBindPipeline(cb, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
        const VkViewport viewport{0.0f, 0.0f, float(f.width), float(f.height), 0.0f, 1.0f};
        const VkRect2D scissor{{0, 0}, {f.width, f.height}};
        vk.CmdSetViewport(cb, 0, 1, &viewport);
        vk.CmdSetScissor(cb, 0, 1, &scissor);
    }
    void endPass(VkCommandBuffer cb, const detail::Generation& g, detail::PassKind pass) {
        if (dynamic()) detail::endDynamicPass(vk, cb, pass, g);
        else vk.CmdEndRenderPass(cb);
    }

    // One foliage pass: SSAM's pipeline, sets and default push constants bound, then the host's draws.
    void foliagePass(const FrameDesc& f, const detail::Generation& g, const detail::FrameFramebuffers* fb,
                     FoliagePass which, const VkClearValue& clear, DrawFoliage draw, void* user) {
        const VkCommandBuffer cb = f.commandBuffer;
        const detail::PassKind kind = which == FoliagePass::Mask ? detail::PassKind::Mask : detail::PassKind::Color;
        beginPass(f, g, fb, kind, &clear, which == FoliagePass::Mask ? g.maskPipeline : g.colorPipeline);
        const VkDescriptorSet sets[] = {frameSet, whiteSet};
        vk.CmdBindDescriptorSets(cb, VK_PIPELINE_BIND_POINT_GRAPHICS, shared.foliageLayout, 0, 2, sets, 0, nullptr);
        const VkDeviceSize offset = 0;
        vk.CmdBindVertexBuffers(cb, settings.vertexLayout.constantsBinding, 1, &constants.buffer, &offset);
        struct {
            float model[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
            float factor[4] = {1, 1, 1, 1};
            std::uint32_t hasTexture = 0;
        } defaults;
        static_assert(sizeof defaults == detail::kFoliagePushSize);
        detail::Recorder recorder{&vk, cb, shared.foliageLayout, &textures, whiteSet};
        recorder.push(0, detail::kFoliagePushSize, &defaults);
        FoliageProgram program;
        program.pass = which;
        program.commandBuffer = cb;
        program.layout = shared.foliageLayout;
        program.alphaReference = which == FoliagePass::Color ? settings.colorAlphaReference : 0.0f;
        program.recorder = &recorder;
        try {
            draw(user, program);
        } catch (const std::exception& e) {
            endPass(cb, g, kind);
            throw Failure(Status::CallbackFailed, std::string("ssam::vk: the draw callback threw in the ") +
                                                      foliagePassName(which) + " pass: " + e.what());
        } catch (...) {
            endPass(cb, g, kind);
            throw Failure(Status::CallbackFailed, std::string("ssam::vk: the draw callback threw in the ") +
                                                      foliagePassName(which) + " pass (not a std::exception)");
        }
        endPass(cb, g, kind);
    }

    void render(const FrameDesc& f, DrawFoliage draw, void* user) {
        expectInitialized("render");
        checkFrame(f);
        retired.collect(f.framesCompleted);
        detail::Generation& g = const_cast<detail::Generation&>(generationFor(f));
        const detail::FrameFramebuffers* fb =
            dynamic() ? nullptr : &g.framebuffersFor(vk, f.colorView, f.depthView, f.frameIndex, retired);
        g.lastUsedFrame = f.frameIndex;
        const VkCommandBuffer cb = f.commandBuffer;
        updateConstants(f, cb);
        // 1. Mask pass (§3.5.2, Table 3.1): cleared to black; RGB = MAX, A = ADD; depth tested, not written.
        VkClearValue clear{};
        foliagePass(f, g, fb, FoliagePass::Mask, clear, draw, user);
        // 2. Colour pass (§3.5.3): cleared to the clear colour (§3.6.1); alpha-tested; depth written (§3.7).
        for (int i = 0; i < 4; ++i) clear.color.float32[i] = settings.foliageClearColor[i];
        foliagePass(f, g, fb, FoliagePass::Color, clear, draw, user);
        // 3. Composite (§3.5.4, Listing 3.2) onto the host's colour.
        beginPass(f, g, fb, detail::PassKind::Composite, nullptr, g.compositePipeline);
        vk.CmdBindDescriptorSets(cb, VK_PIPELINE_BIND_POINT_GRAPHICS, shared.compositeLayout, 0, 1, &g.compositeSet, 0,
                                 nullptr);
        struct {
            float maskLerp;
            std::uint32_t squareMask, hasMaskAdd;
        } push{settings.maskLerp, settings.squareMask ? 1u : 0u, 0u};
        static_assert(sizeof push == detail::kCompositePushSize);
        vk.CmdPushConstants(cb, shared.compositeLayout, VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof push, &push);
        vk.CmdDraw(cb, 3, 1, 0, 0);
        endPass(cb, g, detail::PassKind::Composite);
    }
};

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

void ScreenSpaceAlphaMaskVk::setMessageCallback(MessageCallback callback, void* user) noexcept {
    if (!impl_) return;
    impl_->onMessage = callback;
    impl_->messageUser = user;
}

const char* ScreenSpaceAlphaMaskVk::lastMessage() const noexcept {
    return impl_ ? impl_->lastMessage.c_str()
                 : "ssam::vk: this ScreenSpaceAlphaMaskVk was moved from (or out of memory)";
}

Status ScreenSpaceAlphaMaskVk::initialize(const DeviceDesc& device, const Settings& settings) noexcept {
    if (!impl_) return Status::InvalidCall;
    return impl_->run([&] { impl_->initialize(device, settings); });
}

void ScreenSpaceAlphaMaskVk::release() noexcept {
    if (impl_) impl_->releaseObjects();
}

Status ScreenSpaceAlphaMaskVk::setSettings(const Settings& settings) noexcept {
    if (!impl_) return Status::InvalidCall;
    return impl_->run([&] {
        validate(settings);
        if (!samePipelines(settings, impl_->settings)) ++impl_->settingsVersion;
        impl_->settings = settings;
    });
}

const Settings& ScreenSpaceAlphaMaskVk::settings() const noexcept {
    static const Settings defaults;
    return impl_ ? impl_->settings : defaults;
}

Status ScreenSpaceAlphaMaskVk::createTexture(VkImageView view, VkSampler sampler, TextureId* id) noexcept {
    if (!impl_) return Status::InvalidCall;
    if (id) *id = 0;
    return impl_->run([&] {
        const TextureId made = impl_->createTexture(view, sampler);
        if (id) *id = made;
    });
}

Status ScreenSpaceAlphaMaskVk::destroyTexture(TextureId id, std::uint64_t lastFrameIndex) noexcept {
    if (!impl_) return Status::InvalidCall;
    return impl_->run([&] { impl_->destroyTexture(id, lastFrameIndex); });
}

Status ScreenSpaceAlphaMaskVk::render(const FrameDesc& frame, DrawFoliage draw, void* user) noexcept {
    if (!impl_) return Status::InvalidCall;
    if (!draw) return impl_->fail(Status::InvalidArgument, "ssam::vk: render() without a draw callback");
    return impl_->run([&] { impl_->render(frame, draw, user); });
}

ScreenSpaceAlphaMaskVk::Intermediates ScreenSpaceAlphaMaskVk::intermediates() const noexcept {
    if (!impl_ || !impl_->generation) return {};
    return {impl_->generation->mask.image, impl_->generation->foliage.image};
}

}  // namespace ssam::vk
