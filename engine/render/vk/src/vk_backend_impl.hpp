// SPDX-License-Identifier: MIT
#pragma once
// The Vulkan backend's class, whose members are defined by concern:
//   vk_backend.cpp    creation, tear-down, the frame boundary
//   vk_resources.cpp  textures (images, uploads), buffers (renamed when in flight), programs
//   vk_pipelines.cpp  render passes, framebuffers, samplers and pipelines from resolved state
//   vk_passes.cpp     passes: draws recorded until endPass, barriers, the render pass, queries
//   vk_transfer.cpp   readback and resolve
//   vk_swapchain.cpp  present to the window (the swapchain itself: vk_swapchain.hpp)
// Validation and error messages are the shared ones (validation.hpp), as on soft and GL.
#include <array>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "engine/render/resolved_draw_state.hpp"
#include "engine/render/resource_pool.hpp"
#include "engine/render/standard_programs.hpp"
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
    std::vector<TextureHandle> sampled;
};

class VulkanBackendImpl final : public VulkanBackend {
public:
    VulkanBackendImpl(const VulkanOptions& options, std::unique_ptr<VulkanContext> context);
    ~VulkanBackendImpl() override;

    std::string name() const override { return "vk"; }
    const VulkanInfo& info() const override { return context_->info; }
    const VulkanCounters& counters() const override { return counters_; }
    std::uint64_t validationMessages() const override { return context_->validationMessages; }
    void endFrame() override;

    // vk_resources.cpp
    TextureHandle createTexture(const TextureDesc& desc, const TextureData* data) override;
    BufferHandle createBuffer(const BufferDesc& desc, std::span<const std::byte> data) override;
    void updateBuffer(BufferHandle handle, std::uint64_t offset, std::span<const std::byte> data) override;
    ProgramHandle createProgram(const ProgramDesc& desc) override;
    PipelineHandle createPipeline(const PipelineDesc& desc) override;
    void destroy(TextureHandle h) override;
    void destroy(BufferHandle h) override;
    void destroy(PipelineHandle h) override { pipelines_.remove(h); }
    void destroy(ProgramHandle h) override;
    QueryHandle createQuery(const std::string& name) override;
    void destroy(QueryHandle h) override;
    bool anySamplesPassed(QueryHandle h) override;
    const TextureDesc& describe(TextureHandle h) const override { return textures_.get(h).desc; }
    PipelineInfo pipelineInfo(PipelineHandle h) const override { return pipelines_.get(h).info; }

    // vk_passes.cpp
    void beginPass(const PassDesc& pass) override;
    void draw(const DrawDesc& d) override;
    void endPass() override;
    void abortPass() noexcept override;
    std::vector<PassTiming> takeTimings() override;

    // vk_transfer.cpp
    void resolve(const ResolveDesc& r) override;
    Readback readback(TextureHandle h) override;

    // vk_swapchain.cpp
    bool present(TextureHandle h) override;

private:
    // vk_resources.cpp
    std::shared_ptr<const VulkanProgram> programFor(const ProgramRef& ref);
    std::shared_ptr<const VulkanProgram> buildProgram(std::shared_ptr<const ProgramDesc> desc);
    VkShaderModule fragmentModule(const VulkanProgram& program, int colorTargets);
    int supportedSamples(VkFormat format, bool depth, int wanted, const std::string& what) const;
    void upload(VulkanTexture& t, const TextureData* data);
    void destroyTextureObjects(const VulkanTexture& t);
    void checkDeviceLimits(const TextureDesc& desc, const std::string& what) const;
    MemoryProbe memoryProbe() const;
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
    FailModeEmulation failModeEmulation() const {
        return options_.failModes == FailModeStrategy::PerTriangle ? FailModeEmulation::PerTriangle
                                                                   : FailModeEmulation::TwoPass;
    }

    VulkanOptions options_;
    std::unique_ptr<VulkanContext> context_;
    VulkanCounters counters_;
    std::unique_ptr<FrameRing> frames_;
    std::unique_ptr<Swapchain> swapchain_;  // with a window only
    std::uint64_t heldBytes_ = 0;           // the images' memory (memoryProbe on a GPU)
    ResourcePool<TextureTag, VulkanTexture> textures_;
    ResourcePool<BufferTag, VulkanBuffer> buffers_;
    ResourcePool<PipelineTag, VulkanPipeline> pipelines_;
    ResourcePool<QueryTag, VulkanQuery> queries_;
    ResourcePool<ProgramTag, std::shared_ptr<const VulkanProgram>> programs_;
    ResourceLookup lookup_;
    StandardProgramSlots<VulkanProgram> standardPrograms_;
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
    std::optional<PassDesc> pass_;
    PassExtent extent_;
    int actualSamples_ = 1;
    DrawTargets targets_;
    std::vector<TextureHandle> colorHandles_;
    std::vector<RecordedDraw> draws_;
    bool drawsRun_ = true;  // false: drawOnlyIfSamplesIn found no sample

    // Occlusion queries (one pool, a slot per query handle) and pass timestamps.
    VkQueryPool occlusion_ = VK_NULL_HANDLE, timestamps_ = VK_NULL_HANDLE;
    std::uint32_t occlusionSlots_ = 0;
    std::vector<std::uint32_t> freeOcclusionSlots_;
    struct PendingTiming {
        std::string pass;
        std::uint32_t first = 0;  // its two timestamps
        bool skipped = false;
    };
    std::vector<PendingTiming> pendingTimings_;
    std::uint32_t nextTimestamp_ = 0;
    std::multimap<std::pair<std::uint64_t, BufferKind>, MemoryBuffer> spareBuffers_;  // renamed-out buffers
    TextureHandle dummy_;  // read where an optional texture is absent

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
