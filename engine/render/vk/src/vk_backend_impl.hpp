// SPDX-License-Identifier: MIT
#pragma once
// The Vulkan driver's class, whose members are defined by concern:
//   vk_backend.cpp    creation, tear-down, the frame boundary
//   vk_resources.cpp  textures (images, uploads), buffers (renamed when in flight), programs
//   vk_pipelines.cpp  render passes, framebuffers, samplers and pipelines from resolved state
//   vk_passes.cpp     passes: draws recorded until endPass, barriers, the render pass, queries
//   vk_transfer.cpp   readback and resolve
//   vk_swapchain.cpp  present to the window (the swapchain itself: vk_swapchain.hpp)
// The device (device.hpp) has validated and resolved all it is given, as for soft and GL.
#include <array>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "engine/render/native_slots.hpp"
#include "engine/render/resolved_draw_state.hpp"
#include "engine/render/validation.hpp"
#include "engine/render/vk/vk_backend.hpp"
#include "vk_context.hpp"
#include "vk_frames.hpp"
#include "vk_objects.hpp"
#include "vk_shaders.hpp"
#include "vk_swapchain.hpp"

namespace engine::render::vk {

inline constexpr std::uint32_t kOcclusionSlots = 256;  // occlusion queries alive at once
inline constexpr std::uint32_t kTimestampSlots = 512;  // two per pass between takeTimings calls

// What a render pass object depends on: formats, samples and load operations.
struct RenderPassKey {
    std::array<VkFormat, kMaxColorTargets> color{};
    std::array<std::uint8_t, kMaxColorTargets> load{};  // 1: load, 0: clear
    VkFormat depth = VK_FORMAT_UNDEFINED;
    std::uint8_t depthLoad = 0;
    std::uint8_t colorCount = 0;
    std::uint8_t samples = 1;
    auto operator<=>(const RenderPassKey&) const = default;
};

// A draw recorded in the open pass: what it reads was captured when it was recorded. The
// pipeline's description is copied, not pointed to: a pipeline created later in the same pass
// may grow the pool and move its slots before endPass records the draw.
struct RecordedDraw {
    PipelineDesc pipeline;
    std::shared_ptr<const VulkanProgram> program;
    ResolvedDrawState state;
    std::uint32_t first = 0, count = 0, instanceCount = 1;
    VkBuffer vertices = VK_NULL_HANDLE, indices = VK_NULL_HANDLE, instances = VK_NULL_HANDLE;
    VkBuffer uniforms = VK_NULL_HANDLE;
    std::uint32_t uniformOffset = 0;
    VkDescriptorSet uniformSet = VK_NULL_HANDLE, textureSet = VK_NULL_HANDLE;
    std::vector<NativeId> sampled;
};

class VulkanDriverImpl final : public VulkanDriver {
public:
    VulkanDriverImpl(const VulkanOptions& options, std::unique_ptr<VulkanContext> context);
    ~VulkanDriverImpl() override;

    std::string name() const override { return "vk"; }
    std::string describe() const override { return "vk: " + context_->info.device; }
    void attach(const NativeTextures& textures) override { natives_ = &textures; }
    FailModeEmulation failModeEmulation() const override {
        return options_.failModes == FailModeStrategy::PerTriangle ? FailModeEmulation::PerTriangle
                                                                   : FailModeEmulation::TwoPass;
    }
    const VulkanInfo& info() const override { return context_->info; }
    const VulkanCounters& counters() const override { return counters_; }
    std::uint64_t validationMessages() const override { return context_->validationMessages; }
    void endFrame() override;

    // vk_resources.cpp
    std::uint64_t textureFootprint(const TextureDesc& desc) const override;
    MemoryProbe memoryProbe() const override;
    void checkTexture(const TextureDesc& desc, const TextureData* data, const std::string& what) override;
    void notePipeline(const PipelineDesc& desc, ResolvedPipeline& resolved) override;
    NativeId createQuery(const std::string& name) override;
    // vk_swapchain.cpp
    bool present(NativeId h, const TextureDesc& desc) override;

    // The driver calls: resources and queries in vk_resources.cpp, passes, draws and timings in
    // vk_passes.cpp, resolves and readbacks in vk_transfer.cpp.
    ENGINE_DRIVER_CALLS(ENGINE_DRIVER_OVERRIDE)

private:
    // vk_resources.cpp
    std::shared_ptr<const VulkanProgram> buildProgram(std::shared_ptr<const ProgramDesc> desc);
    VkShaderModule fragmentModule(const VulkanProgram& program, int colorTargets);
    int supportedSamples(VkFormat format, bool depth, int wanted, const std::string& what) const;
    VkImageCreateInfo imageInfo(const TextureDesc& desc, int actualSamples) const;
    void upload(VulkanTexture& t, const TextureData* data);
    void destroyTextureObjects(const VulkanTexture& t);
    void checkDeviceLimits(const TextureDesc& desc, const std::string& what) const;
    VulkanBuffer makeBuffer(const BufferDesc& desc, const std::string& what);

    // vk_pipelines.cpp
    VkRenderPass renderPass(const RenderPassKey& key);
    VkFramebuffer framebuffer(VkRenderPass pass, const std::vector<VkImageView>& views, int width, int height);
    VkSampler sampler(const SamplerState& s);
    VkPipeline pipeline(const VulkanProgram& program, const PipelineDesc& desc, const ResolvedDrawState& state,
                        const PlanStep& step, const RenderPassKey& pass);
    void forgetFramebuffers(VkImageView view);

    // vk_passes.cpp: barriers before the next use of an image (ImageState).
    void use(VkCommandBuffer cmd, VulkanTexture& t, VkImageLayout layout, VkPipelineStageFlags stage,
             VkAccessFlags access, bool writes);
    void recordPass();

    VulkanOptions options_;
    std::unique_ptr<VulkanContext> context_;
    VulkanCounters counters_;
    std::unique_ptr<FrameRing> frames_;
    std::unique_ptr<Swapchain> swapchain_;     // with a window only
    std::uint64_t heldBytes_ = 0;              // the images' memory (memoryProbe on a GPU)
    const NativeTextures* natives_ = nullptr;  // the device's handles, for the textures a draw samples
    NativeSlots<VulkanTexture> textures_;
    NativeSlots<VulkanBuffer> buffers_;
    NativeSlots<VulkanQuery> queries_;
    NativeSlots<std::shared_ptr<const VulkanProgram>> programs_;
    MemoryBuffer identityInstance_;

    std::map<RenderPassKey, VkRenderPass> renderPasses_;
    struct FramebufferKey {
        VkRenderPass pass;
        std::vector<VkImageView> views;
        int width, height;
        auto operator<=>(const FramebufferKey&) const = default;
    };
    std::map<FramebufferKey, VkFramebuffer> framebuffers_;
    std::map<int, VkSampler> samplers_;

    // The open pass.
    std::optional<DriverPass> pass_;
    PassExtent extent_;
    int actualSamples_ = 1;
    std::vector<RecordedDraw> draws_;
    bool drawsRun_ = true;  // false: drawOnlyIfSamplesIn found no sample

    // Occlusion queries (one pool, a slot per query handle) and pass timestamps.
    VkQueryPool occlusion_ = VK_NULL_HANDLE, timestamps_ = VK_NULL_HANDLE;
    std::uint32_t occlusionSlots_ = 0;
    std::vector<std::uint32_t> freeOcclusionSlots_;
    struct PendingTiming {
        std::uint64_t serial = 0;
        std::string pass;
        std::uint32_t first = 0;  // its two timestamps
        bool skipped = false;
    };
    std::vector<PendingTiming> pendingTimings_;
    std::uint32_t nextTimestamp_ = 0;
    std::multimap<std::pair<std::uint64_t, BufferKind>, MemoryBuffer> spareBuffers_;  // renamed-out buffers
    NativeId dummy_ = kNoNative;  // read where an optional texture is absent

    // The backend's own resolve pipelines, per destination format.
    struct ResolvePipelines {
        VkShaderModule vertex = VK_NULL_HANDLE, color = VK_NULL_HANDLE, depth = VK_NULL_HANDLE;
        VkDescriptorSetLayout setLayout = VK_NULL_HANDLE;
        VkPipelineLayout layout = VK_NULL_HANDLE;
        std::map<VkFormat, VkPipeline> pipelines;
    } resolve_;
    VkPipeline resolveProgramPipeline(VkFormat format, bool depth, VkRenderPass pass);
    void destroyResolvePipelines();
};

}  // namespace engine::render::vk
