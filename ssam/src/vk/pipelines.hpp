// SPDX-License-Identifier: MIT
#pragma once
// ssam::vk's Vulkan objects: those made once (shader modules from the embedded SPIR-V, descriptor
// set and pipeline layouts, samplers) and a Generation -- what depends on the frame's formats and
// size and on the settings (render passes, pipelines, intermediate images). A frame with another
// key makes a new Generation and retires the old one. The framebuffers over the host's views are
// made per frame (FrameFramebuffers, frame_scoped.hpp): they name objects SSAM does not own.
#include <cstdint>
#include <vector>

#include "resources.hpp"

namespace ssam::vk::detail {

// Push constants of the foliage programs (glsl_variants.cpp: model 0, factor 64, hasTexture 80)
// and of the composite (maskLerp 0, squareMask 4, hasMaskAdd 8, colorFade 16, colorBlur 24, foliageClear 32;
// the depth restore also reads threshold at 12).
inline constexpr std::uint32_t kFoliagePushSize = 84;
inline constexpr std::uint32_t kCompositePushSize = 44;
inline constexpr std::uint32_t kRestorePushSize = 44;

// DepthRestore: Settings::depthMaskThreshold's depth-only pass after the composite.
enum class PassKind { Mask, Color, Composite, DepthRestore };

// MaskPrecision::Rg16f's two single-channel mask targets (MAX, ADD).
inline constexpr VkFormat kMaskPairFormat = VK_FORMAT_R16_SFLOAT;

// The fixed-function state of a pass's pipeline: SSAM's own use it, and pipelineState() hands it
// to the host's (way b).
void fixedState(PassKind pass, const Settings& settings, PipelineState& state);

// A render pass of SSAM's (RenderPass path): `target` cleared (mask, colour) or loaded (composite),
// the host's depth loaded and stored (none for the composite: VK_FORMAT_UNDEFINED); the mask
// pass's target kMaskPairFormat means two of them (Rg16f); the depth restore has the depth only.
VkRenderPass createPassFor(const VkFunctions& vk, PassKind pass, VkFormat target, VkFormat depth);

struct SharedObjects {
    VkShaderModule foliageVertex = VK_NULL_HANDLE, maskVertex = VK_NULL_HANDLE, maskFragment = VK_NULL_HANDLE,
                   maskPairFragment = VK_NULL_HANDLE, colorFragment = VK_NULL_HANDLE, fullscreenVertex = VK_NULL_HANDLE,
                   compositeFragment = VK_NULL_HANDLE, restoreFragment = VK_NULL_HANDLE;
    VkDescriptorSetLayout frameSetLayout = VK_NULL_HANDLE;      // set 0: the frame's uniform block
    VkDescriptorSetLayout textureSetLayout = VK_NULL_HANDLE;    // set 1: the base-colour texture
    VkDescriptorSetLayout compositeSetLayout = VK_NULL_HANDLE;  // rt_foliage, mask, mask (add)
    VkDescriptorSetLayout restoreSetLayout = VK_NULL_HANDLE;    // the composite's + the saved depth
    VkPipelineLayout foliageLayout = VK_NULL_HANDLE, compositeLayout = VK_NULL_HANDLE, restoreLayout = VK_NULL_HANDLE;
    VkSampler linearSampler = VK_NULL_HANDLE;   // host textures without a sampler of their own
    VkSampler nearestSampler = VK_NULL_HANDLE;  // the composite's texelFetch

    void create(const VkFunctions& vk);
    void destroy(const VkFunctions& vk) noexcept;
};

struct GenerationKey {
    VkFormat colorFormat = VK_FORMAT_UNDEFINED, depthFormat = VK_FORMAT_UNDEFINED, maskFormat = VK_FORMAT_UNDEFINED;
    std::uint32_t width = 0, height = 0;
    std::uint64_t settingsVersion = 0;
    bool depthRestore = false;  // Settings::depthMaskThreshold > 0
    bool maskPair() const { return maskFormat == kMaskPairFormat; }
    bool operator==(const GenerationKey& o) const {
        return colorFormat == o.colorFormat && depthFormat == o.depthFormat && maskFormat == o.maskFormat &&
               width == o.width && height == o.height && settingsVersion == o.settingsVersion &&
               depthRestore == o.depthRestore;
    }
};

// One frame's framebuffers (RenderPass path) over the host's views and SSAM's intermediates.
struct FrameFramebuffers {
    VkFramebuffer mask = VK_NULL_HANDLE, color = VK_NULL_HANDLE, composite = VK_NULL_HANDLE, restore = VK_NULL_HANDLE;
};
void destroyFramebuffers(const VkFunctions& vk, const FrameFramebuffers& framebuffers) noexcept;

struct Generation {
    GenerationKey key;
    VkRenderPass maskPass = VK_NULL_HANDLE, colorPass = VK_NULL_HANDLE, compositePass = VK_NULL_HANDLE,
                 restorePass = VK_NULL_HANDLE;
    VkPipeline maskPipeline = VK_NULL_HANDLE, colorPipeline = VK_NULL_HANDLE, compositePipeline = VK_NULL_HANDLE,
               restorePipeline = VK_NULL_HANDLE;
    Image mask, maskAdd, foliage;  // maskAdd: Rg16f only
    Image savedDepth;              // depthRestore only: the opaque depth, copied before the colour pass
    VkDescriptorPool pool = VK_NULL_HANDLE;
    VkDescriptorSet compositeSet = VK_NULL_HANDLE, restoreSet = VK_NULL_HANDLE;
    std::uint64_t lastUsedFrame = 0;

    // dynamicRendering: no render passes (the pipelines take VkPipelineRenderingCreateInfo) and
    // no framebuffers.
    void create(const VkFunctions& vk, const MemorySource& memory, const SharedObjects& shared,
                const GenerationKey& key, const Settings& settings, const VertexLayout& layout, bool dynamicRendering);
    void destroy(const VkFunctions& vk, const MemorySource& memory) noexcept;
    // New framebuffers over the host's views for one frame (never reused for another: the
    // caller keeps them in a FrameScoped); none made if one fails.
    FrameFramebuffers createFramebuffers(const VkFunctions& vk, VkImageView color, VkImageView depth) const;
};

}  // namespace ssam::vk::detail
