// SPDX-License-Identifier: MIT
#pragma once
// ssam::vk's state behind the public class: what initialize() made (ssam_vk.cpp) and the frame
// being recorded (frame.cpp).
#include <cstddef>
#include <cstdint>
#include <memory>
#include <new>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "../core/frame_sequence.hpp"
#include "../core/host_channel.hpp"
#include "dynamic_rendering.hpp"
#include "failure.hpp"
#include "frame_scoped.hpp"
#include "pipelines.hpp"
#include "resources.hpp"
#include "vk_functions.hpp"

namespace ssam::vk {

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
inline constexpr std::uint32_t kFrameBlockSize = 128;
static_assert(sizeof(Constants) == 256 + 28 * 4, "Constants' layout is pipelines.cpp's and the shaders'");

// The composite's push constants (glsl_variants.cpp); the depth restore's adds the threshold.
struct CompositePush {
    float maskLerp;
    std::uint32_t squareMask, hasMaskAdd;
    float threshold;     // the depth restore only
    float colorFade[2];  // core::ColorFade's start, end (std430: a vec2 at 16)
    std::uint32_t colorBlur, pad;
    float foliageClear[3];  // a vec3 at 32
};
static_assert(sizeof(CompositePush) == kRestorePushSize && sizeof(CompositePush) == kCompositePushSize &&
              offsetof(CompositePush, threshold) == 12 && offsetof(CompositePush, colorFade) == 16 &&
              offsetof(CompositePush, colorBlur) == 24 && offsetof(CompositePush, foliageClear) == 32);

// Where a frame is: each call of way (b) moves it one step, in this order only (the core's).
using core::Phase;

}  // namespace detail

using detail::Failure;

struct ScreenSpaceAlphaMaskVk::Impl {
    detail::VkFunctions vk;
    DeviceDesc device;
    bool initialized = false;
    Settings settings;
    std::uint64_t settingsVersion = 0;
    VertexLayout vertexLayout;
    core::HostChannel channel{"ssam::vk"};

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
    // RenderPass path: each frame's framebuffers over the host's views, until the frame completes.
    detail::FrameScoped<detail::FrameFramebuffers> frameFramebuffers;
    // The last frame begun (beginFrame): frame numbers may repeat, not go back.
    std::optional<std::uint64_t> lastFrameIndex;
    std::uint64_t lastFramesCompleted = 0;
    bool warnedFramesNotCompleting = false;
    // VkPhysicalDeviceLimits SSAM's targets must keep to (initialize).
    std::uint32_t maxFramebufferWidth = 0, maxFramebufferHeight = 0, maxImageDimension2D = 0;

    // The open frame (way b, and way a through it).
    detail::Phase phase = detail::Phase::Idle;
    FrameDesc frame;
    detail::FrameFramebuffers framebuffers;  // RenderPass path: this frame's (also in frameFramebuffers)
    Rect region;                             // the composite's scissor

    // Way (b): render passes compatible with SSAM's, handed out by pipelineState().
    struct CompatiblePass {
        detail::PassKind kind;
        VkFormat target, depth;
        VkRenderPass pass;
    };
    std::vector<CompatiblePass> compatiblePasses;
    std::uint64_t pipelineStateVersion = 0;  // changed by a setSettings() that changes PipelineState
    static constexpr std::uint32_t kTexturesPerPool = 64;

    // ---- Objects made once ----------------------------------------------------------------

    // ---- Host textures ------------------------------------------------------------------

    // ---- The frame ------------------------------------------------------------------------

    bool dynamic() const { return device.renderingPath == RenderingPath::DynamicRendering; }

    void message(Severity severity, const std::string& text) noexcept { channel.message(severity, text); }
    Status fail(Status status, const char* text) noexcept { return channel.fail(status, text); }
    // Runs one public call: Ok, or the Failure's status with its message; a frame call that fails
    // abandons the open frame (abandonFrame), a query or a texture call (`frameCall` false) leaves it.
    template <class Body>
    Status run(Body&& body, bool frameCall = true) noexcept {
        return channel.run(std::forward<Body>(body), [this, frameCall]() noexcept {
            if (frameCall) abandonFrame();
        });
    }
    void expectInitialized(const char* call) const {
        if (!initialized) throw Failure(Status::InvalidCall, std::string("ssam::vk: ") + call + " before initialize()");
    }

    void initialize(const DeviceDesc& desc, const Settings& wanted, const VertexLayout& wantedLayout);
    void releaseObjects() noexcept;
    TextureId createTexture(VkImageView view, VkSampler sampler);
    void destroyTexture(TextureId id, std::uint64_t lastFrame);
    VkFormat maskFormat() const;
    void checkFormat(VkFormat format, VkFormatFeatureFlags needed, const char* what) const;
    void checkFrame(const FrameDesc& f) const;
    void checkSize(const FrameDesc& f) const;
    // A host whose framesCompleted stays put piles up per-frame framebuffers: said once (Warning).
    void warnIfFramesDoNotComplete() noexcept;
    const detail::Generation& generationFor(const FrameDesc& f);
    void updateConstants(const FrameDesc& f, VkCommandBuffer cb);
    // A pass begun on either path (RenderingPath), its pipeline bound, viewport and scissor the frame.
    void beginPass(const FrameDesc& f, const detail::Generation& g, const detail::FrameFramebuffers* fb,
                   detail::PassKind pass, const VkClearValue* clear, VkPipeline pipeline);
    void endPass(VkCommandBuffer cb, const detail::Generation& g, detail::PassKind pass);
    void checkFormats(VkFormat colorFormat, VkFormat depthFormat) const;
    // The frame, one step at a time (way b; way a through it).
    void expect(detail::Phase expected, const char* call) const;
    void abandonFrame() noexcept;
    FrameReport beginFrame(const FrameDesc& f);
    PassInfo beginFoliagePass(FoliagePass which);
    void endFoliagePass(FoliagePass which);
    void drawBuiltIn(const PassInfo& pass, DrawFoliage draw, void* user);
    void compositeFrame();
    // Settings::depthMaskThreshold (depth_restore.cpp): the host's depth copied over the region
    // before the colour pass; after the composite, written back where the mask is below it.
    void saveOpaqueDepth(const detail::Generation& g);
    void restoreDepth(const detail::Generation& g, const detail::CompositePush& push);
    FrameReport render(const FrameDesc& f, DrawFoliage draw, void* user);
    PipelineState pipelineStateFor(FoliagePass pass, VkFormat colorFormat, VkFormat depthFormat);
};

}  // namespace ssam::vk
