// SPDX-License-Identifier: MIT
#pragma once
// SSAM for engines that bring their own Vulkan ([Hathaway 2010] §3.5-3.7). SSAM records its mask,
// colour and composite passes into the host's command buffer, on the host's device: it composites
// onto the host's colour image and writes the foliage depth into the host's depth image (for
// later transparent passes, §3.7). It never submits, waits or touches a queue.
//
// Host-neutral: standard C++17, <ssam/version.hpp> and <vulkan/vulkan.h> (types only; define
// VK_NO_PROTOTYPES or not, as the host likes). No link-time dependency on libvulkan: every Vulkan
// function is resolved through the host's vkGetInstanceProcAddr / vkGetDeviceProcAddr. Nothing
// throws into host code: every call returns a Status, and the reason goes to an optional message
// callback and lastMessage(). SPIR-V is compiled when SSAM is built and carried inside the library.
//
// Two ways to draw the foliage, as ssam::gl's:
//  (a) SSAM's built-in foliage programs: render(frame, draw) records the three passes and calls
//      `draw` twice (mask pass, then colour pass) inside SSAM's render pass with SSAM's pipeline
//      bound; the host binds its vertex (and index) buffers as the VertexLayout given to initialize() describes,
//      sets per-draw values through FoliageProgram and records its draws.
//  (b) The host's own pipelines: beginFrame(), then beginMaskPass() / draws / endMaskPass(),
//      beginColorPass() / draws / endColorPass(), composite(). The host creates its mask and colour
//      pipelines with the fixed-function state pipelineState() hands out (blend, depth-stencil,
//      rasterization, multisample, the render pass or attachment formats; viewport and scissor
//      dynamic: SSAM sets them), and its shaders keep ssam::gl's host-shader contract
//      (ssam/gl/ssam_gl.hpp): the mask pass writes vec4(a) to location 0 (and to location 1 when
//      PassInfo::colorAttachmentCount is 2: MaskPrecision::Rg16f) and does not alpha-test,
//      the colour pass writes (rgb, a) and discards !(a >= PassInfo::alphaReference).
// With DeviceDesc::renderingPath DynamicRendering, "render pass" below means SSAM's
// vkCmdBeginRendering scope.
//
// The synchronization contract (FrameDesc::commandBuffer, outside any render pass):
//   host colour  entry: COLOR_ATTACHMENT_OPTIMAL, last written at COLOR_ATTACHMENT_OUTPUT
//                       (COLOR_ATTACHMENT_WRITE)
//                SSAM:  the composite loads, blends and stores it
//                exit:  COLOR_ATTACHMENT_OPTIMAL, SSAM's writes at COLOR_ATTACHMENT_OUTPUT
//   host depth   entry: DEPTH_STENCIL_ATTACHMENT_OPTIMAL, last written at EARLY/LATE_FRAGMENT_TESTS
//                       (DEPTH_STENCIL_ATTACHMENT_WRITE)
//                SSAM:  mask pass tests it; colour pass tests and writes it; stencil kept as is;
//                       depthMaskThreshold > 0: copied (TRANSFER_SRC_OPTIMAL, SSAM's barriers, back
//                       before the colour pass) and rewritten by a depth-only pass after the composite
//                exit:  DEPTH_STENCIL_ATTACHMENT_OPTIMAL, SSAM's writes at EARLY/LATE_FRAGMENT_TESTS
// SSAM's render passes carry the external dependencies for exactly those stages and accesses, in
// and out (on the dynamic-rendering path, pipeline barriers of the same stages and accesses): a
// host whose last access was another stage (a transfer, a compute write, a sampled read) records
// its own barrier into the entry row first, and one out of the exit row before it uses the images
// another way (e.g. copies the colour out: COLOR_ATTACHMENT_OUTPUT / COLOR_ATTACHMENT_WRITE ->
// TRANSFER / TRANSFER_READ). Between its passes SSAM records its own barriers (its uniform update,
// its intermediates), and it never waits on the device.
//
// Lifetime: SSAM's own objects (render passes, pipelines, its intermediate images) live until
// release() or the destructor, which need the host's device idle for them (vkDeviceWaitIdle, or
// every command buffer SSAM recorded into completed). What SSAM replaces while running
// (intermediates on a resize) it destroys once FrameDesc::framesCompleted says no frame that used
// them is still in flight. Nothing SSAM keeps outlives a host object it names: the framebuffers
// over the host's views (RenderPass path) are made for each frame and destroyed once
// framesCompleted passes it, never looked up again by the views' handle values (a recreated view
// may get a destroyed one's value back), so the host may destroy and recreate its targets as soon
// as the frames that used them completed, with no call to SSAM.
// The host keeps alive until then: its device, its image views given in FrameDesc, its vertex
// buffers and textures (and their samplers) bound through FoliageProgram.
//
// What SSAM checks: its own call order, every FrameDesc / Settings / DeviceDesc field it can
// judge (sizes against the device's limits and the declared image extents, formats, finite
// matrices and bounds, frame numbers). What only the validation layer sees (Vulkan has no query
// for them): a command buffer not recording or inside a render pass, images not in the contract's
// layouts, destroyed or wrong views (another image, level, usage or a format unlike the one
// declared), extents declared wrong, and the host's own draws (ssam/docs/vk_host_checks.md).
#include <cstddef>
#include <cstdint>
#include <memory>
#include <type_traits>

#include <vulkan/vulkan.h>

#include "ssam/core/frame.hpp"
#include "ssam/core/host_passes.hpp"
#include "ssam/core/settings.hpp"
#include "ssam/core/status.hpp"
#include "ssam/version.hpp"  // SSAM_VERSION_MAJOR / MINOR / PATCH, generated (cmake/package.cmake)

namespace ssam::vk {

// ---- Results (the core's: ssam/core/status.hpp) -------------------------------------------

using ssam::MessageCallback;
using ssam::Severity;
using ssam::severityName;
using ssam::Status;
using ssam::StatusCode;
using ssam::statusName;

// Device memory for SSAM's intermediate images, from the host's allocator (optional: without one
// SSAM makes one vkAllocateMemory per image). allocate() returns VK_SUCCESS with a block of
// `requirements.size` bytes at `*offset` of `*memory`, aligned and of a type allowed by
// `requirements`, with `properties` (DEVICE_LOCAL); release() gets back what allocate() gave.
struct DeviceMemoryCallbacks {
    void* user = nullptr;
    VkResult (*allocate)(void* user, const VkMemoryRequirements& requirements, VkMemoryPropertyFlags properties,
                         VkDeviceMemory* memory, VkDeviceSize* offset) = nullptr;
    void (*release)(void* user, VkDeviceMemory memory, VkDeviceSize offset) = nullptr;
};

// How SSAM records its passes. RenderPass: VkRenderPass + VkFramebuffer, whose external
// dependencies are the contract (the 1.3.239 layers' synchronization validation checks this
// path). DynamicRendering: vkCmdBeginRendering with pipeline barriers of the same stages and
// accesses (no render pass or framebuffer objects); needs the host's dynamicRendering feature.
enum class RenderingPath : int { RenderPass, DynamicRendering };

// The host's Vulkan, as it created it. SSAM uses the device from one thread at a time (the
// host's recording thread) and creates its objects with `allocationCallbacks`.
struct DeviceDesc {
    VkInstance instance = VK_NULL_HANDLE;
    VkPhysicalDevice physicalDevice = VK_NULL_HANDLE;
    VkDevice device = VK_NULL_HANDLE;
    std::uint32_t queueFamily = 0;  // the family of the queue the host submits SSAM's frames on (graphics)
    std::uint32_t apiVersion = 0;   // what the host gave VkApplicationInfo::apiVersion; 1.0 or newer
    // Features the host enabled. dynamicRendering: Vulkan 1.3's (or VK_KHR_dynamic_rendering's);
    // independentBlend (VkPhysicalDeviceFeatures): needed by MaskPrecision::Rg16f, whose two mask
    // attachments blend differently; synchronization2 is not used yet (SSAM records vkCmdPipelineBarrier).
    bool dynamicRendering = false;
    bool independentBlend = false;
    bool synchronization2 = false;
    RenderingPath renderingPath = RenderingPath::RenderPass;
    PFN_vkGetInstanceProcAddr getInstanceProcAddr = nullptr;
    PFN_vkGetDeviceProcAddr getDeviceProcAddr = nullptr;  // optional: resolved through the instance's
    const VkAllocationCallbacks* allocationCallbacks = nullptr;
    DeviceMemoryCallbacks memory;  // optional
};

// ---- Plain data ----------------------------------------------------------------------------

// The core's (ssam/core/frame.hpp): Rect (pixels, rows from the top: Vulkan's framebuffer y), Box,
// Light (the built-in colour program's).
using ssam::Box;
using ssam::Light;
using ssam::Rect;

// Where the built-in programs read the host's vertex buffers: each attribute's binding, format
// and offset (any format Vulkan converts to the shader's float vector: e.g. R32G32B32_SFLOAT for
// the position, R8G8B8A8_UNORM for the colour). An absent attribute (format VK_FORMAT_UNDEFINED)
// reads SSAM's constant: normal (0,0,1), uv (0,0), colour and instance tint (1,1,1,1), instance
// model the identity, from a buffer SSAM binds at `constantsBinding`, which the host must leave
// alone in the draw callback. The tint's alpha is how a host crossfades two levels of detail
// through the mask, sort-free: each level's instances carry its weight.
struct VertexAttribute {
    std::uint32_t binding = 0;
    VkFormat format = VK_FORMAT_UNDEFINED;
    std::uint32_t offset = 0;
};
struct VertexBinding {
    std::uint32_t binding = 0;
    std::uint32_t stride = 0;
    VkVertexInputRate inputRate = VK_VERTEX_INPUT_RATE_VERTEX;
};
struct VertexLayout {
    static constexpr std::size_t kMaxBindings = 4;
    // Every element spelled out: GCC 12 rejects `Settings s; s = {};` when an array member's
    // initializer leaves elements to brace elision.
    VertexBinding bindings[kMaxBindings] = {VertexBinding{0, 12, VK_VERTEX_INPUT_RATE_VERTEX}, VertexBinding{},
                                            VertexBinding{}, VertexBinding{}};
    std::uint32_t bindingCount = 1;
    VertexAttribute position{0, VK_FORMAT_R32G32B32_SFLOAT, 0};  // vec3, required
    VertexAttribute normal;                                      // vec3, double-sided lighting
    VertexAttribute uv;                                          // vec2, base-colour texture coordinates
    VertexAttribute color;                                       // vec4, multiplies the base colour
    VertexAttribute instanceModel;  // mat4 as 4 vec4 columns at offset, + 16, + 32, + 48 (R32G32B32A32_SFLOAT)
    // vec4 per instance, multiplies the colour (straight alpha): a four-channel format read as
    // float that every device takes for vertex buffers (R32G32B32A32_SFLOAT, R16G16B16A16_SFLOAT /
    // UNORM / SNORM, R8G8B8A8_UNORM / SNORM, B8G8R8A8_UNORM, A8B8G8R8_UNORM / SNORM_PACK32,
    // A2B10G10R10_UNORM_PACK32).
    VertexAttribute instanceTint;
    std::uint32_t constantsBinding = 15;  // below maxVertexInputBindings (16 at least); not one of `bindings`
};

// The paper's knobs (ssam/core/settings.hpp), the same struct for every SSAM. Rg16f needs the
// host's independentBlend feature (DeviceDesc::independentBlend: its two mask attachments blend
// MAX and ADD). depthMaskThreshold > 0: SSAM copies the opaque depth (FrameDesc::depthImage)
// before the colour pass and writes it back after the composite where the mask is below it, both
// over the composite's region (one depth copy and one full-screen depth-only pass).
using ssam::DepthTest;
using ssam::MaskPrecision;
using ssam::Settings;

struct FrameDesc {
    // In the recording state, outside a render pass, of the queue family DeviceDesc names.
    VkCommandBuffer commandBuffer = VK_NULL_HANDLE;
    // The host's opaque colour: a single-sample 2D view (one level, one layer) with
    // COLOR_ATTACHMENT usage, in R8G8B8A8_UNORM / _SRGB, B8G8R8A8_UNORM / _SRGB,
    // R16G16B16A16_SFLOAT or R32G32B32A32_SFLOAT (sRGB blends in linear, as Vulkan does).
    VkImageView colorView = VK_NULL_HANDLE;
    VkFormat colorFormat = VK_FORMAT_UNDEFINED;
    // Required: the extent of colorView's image at the view's level (VkImageCreateInfo::extent for
    // a view of level 0). Vulkan cannot tell SSAM a view's size: SSAM renders width x height into
    // it, and refuses a frame larger than this (InvalidArgument) instead of writing past the image.
    VkExtent2D colorImageExtent{0, 0};
    // Its depth: D16_UNORM, X8_D24_UNORM_PACK32, D32_SFLOAT, D24_UNORM_S8_UINT or D32_SFLOAT_S8_UINT,
    // DEPTH_STENCIL_ATTACHMENT usage. Receives the foliage depth.
    VkImageView depthView = VK_NULL_HANDLE;
    VkFormat depthFormat = VK_FORMAT_UNDEFINED;
    VkExtent2D depthImageExtent{0, 0};  // required: as colorImageExtent, of depthView's image
    // The image of depthView: needed only with Settings::depthMaskThreshold > 0, then created with
    // TRANSFER_SRC usage (SSAM copies its depth aspect, see the contract above).
    VkImage depthImage = VK_NULL_HANDLE;
    // The frame SSAM renders, from the images' top-left corner: 1 to the device's
    // maxFramebufferWidth / Height and maxImageDimension2D, and within both declared extents.
    std::uint32_t width = 0;
    std::uint32_t height = 0;
    // Column-major, finite, in the host's clip conventions (Vulkan's: y down, z in [0, w] unless the
    // host's projection says otherwise; SSAM draws with a viewport of the whole frame, y down).
    float viewProj[16] = {1.0f, 0.0f, 0.0f, 0.0f, 0.0f, 1.0f, 0.0f, 0.0f,
                          0.0f, 0.0f, 1.0f, 0.0f, 0.0f, 0.0f, 0.0f, 1.0f};
    Light light;
    // World-space boxes around everything the host will draw. Given (count > 0): when none is in
    // view nothing is recorded (SSAM costs nothing, the callback is not called) and the composite
    // is scissored to their screen region. Not given: every pass covers the whole frame. Each box
    // finite, min <= max, with an extent in two axes at least (flat in one: a card is fine).
    const Box* foliageBounds = nullptr;
    std::size_t foliageBoundsCount = 0;
    // Deferred destruction (N frames in flight is the host's choice): `frameIndex` numbers the
    // frame being recorded (increasing); every frame numbered below `framesCompleted` has finished
    // on the device (its fence signalled). Objects SSAM retires are destroyed once no frame that
    // used them can still run. framesCompleted = frameIndex: nothing is in flight. Neither may go
    // back from one frame to the next (several SSAM frames in one host frame may share numbers);
    // framesCompleted must move on, or what SSAM retires (each frame's framebuffers) piles up.
    std::uint64_t frameIndex = 0;
    std::uint64_t framesCompleted = 0;
};

// The core's (ssam/core/frame.hpp): FrameReport (compositeRegion rows from the top), FoliagePass.
using ssam::FoliagePass;
using ssam::foliagePassName;
using ssam::FrameReport;

// A host texture for the built-in programs (createTexture); 0 is "none".
using TextureId = std::uint32_t;

namespace detail {
struct Recorder;
}

// What the draw callback gets (way a). Clip position = viewProj (FrameDesc) * model (setModel) *
// instanceModel (attribute) * position. Base = factor * colour * instanceTint * texel; the colour
// pass discards base.a < alphaReference and writes base.rgb * (ambient + light * lambert). SSAM's
// pipeline is bound, with its descriptor sets and push constants: the host records
// vkCmdBindVertexBuffers / vkCmdBindIndexBuffer / vkCmdDraw* (and nothing that binds another
// pipeline, descriptor set or the constants binding) into `commandBuffer`.
struct FoliageProgram {
    FoliagePass pass = FoliagePass::Mask;
    VkCommandBuffer commandBuffer = VK_NULL_HANDLE;
    VkPipelineLayout layout = VK_NULL_HANDLE;  // push constants: model (0), factor (64), hasTexture (80)
    float alphaReference = 0.0f;               // colour pass: Settings::colorAlphaReference; mask pass: 0

    void setModel(const float columnMajor[16]) const noexcept;                   // identity until set
    void setBaseColorFactor(float r, float g, float b, float a) const noexcept;  // (1,1,1,1) until set
    // A texture from createTexture (straight alpha), or 0 for none (texel = (1,1,1,1)).
    void bindBaseColorTexture(TextureId texture) const noexcept;

    const detail::Recorder* recorder = nullptr;  // SSAM's (internal)
};

// What a pass of the host's own pipelines must know (way b).
struct PassInfo {
    FoliagePass pass = FoliagePass::Mask;
    VkCommandBuffer commandBuffer = VK_NULL_HANDLE;  // FrameDesc's, inside SSAM's render pass
    float alphaReference = 0.0f;                     // colour pass: discard when !(alpha >= it); mask pass 0
    // 2 in the mask pass with MaskPrecision::Rg16f: the host's shader writes vec4(a) to location 1 too.
    std::uint32_t colorAttachmentCount = 1;
};

// The fixed-function state of a pass's pipeline (way b): create the host's pipeline with these
// (pColorBlendState: colorAttachmentCount attachments, blendAttachments), viewport and scissor
// dynamic, and renderPass + subpass 0 (RenderingPath::RenderPass) or a
// VkPipelineRenderingCreateInfo of these formats (RenderingPath::DynamicRendering). `version` is
// pipelineStateVersion() when it was handed out: a setSettings() that changes this state
// (depthTest, maskPrecision) changes it. The mask pass with MaskPrecision::Rg16f has two colour
// attachments (MAX, then ADD: they blend differently, hence independentBlend).
struct PipelineState {
    std::uint32_t colorAttachmentCount = 1;
    VkPipelineColorBlendAttachmentState blendAttachments[2]{};
    // Filled whole by pipelineState() (sType included; pNext null).
    VkPipelineDepthStencilStateCreateInfo depthStencil{};
    VkPipelineRasterizationStateCreateInfo rasterization{};
    VkPipelineMultisampleStateCreateInfo multisample{};
    VkRenderPass renderPass = VK_NULL_HANDLE;  // RenderPass path; SSAM's until release()
    VkFormat colorAttachmentFormats[2] = {VK_FORMAT_UNDEFINED, VK_FORMAT_UNDEFINED};
    VkFormat depthAttachmentFormat = VK_FORMAT_UNDEFINED;
    VkFormat stencilAttachmentFormat = VK_FORMAT_UNDEFINED;
    std::uint64_t version = 0;
};

// ---- SSAM ----------------------------------------------------------------------------------

// From HostPasses (ssam/core/host_passes.hpp): setMessageCallback, lastMessage, settings, render
// (way a), beginFrame ... composite (way b), recorded into FrameDesc::commandBuffer.
class ScreenSpaceAlphaMaskVk : public HostPasses<ScreenSpaceAlphaMaskVk, FrameDesc, FoliageProgram, PassInfo> {
public:
    ScreenSpaceAlphaMaskVk() noexcept;  // no Vulkan yet
    ~ScreenSpaceAlphaMaskVk();          // release()
    ScreenSpaceAlphaMaskVk(ScreenSpaceAlphaMaskVk&&) noexcept;
    ScreenSpaceAlphaMaskVk& operator=(ScreenSpaceAlphaMaskVk&&) noexcept;

    // Resolves SSAM's Vulkan functions through the host's loader (MissingEntryPoint names the
    // first one missing) and creates what does not depend on a frame: shader modules, layouts,
    // samplers, its small constants buffer. May be called again after release().
    // `vertexLayout`: what the built-in programs read of the host's vertex buffers (way a).
    Status initialize(const DeviceDesc& device, const Settings& settings = {},
                      const VertexLayout& vertexLayout = {}) noexcept;
    // Destroys every object SSAM made; the host's device must be idle for them (see Lifetime above).
    void release() noexcept;

    // InvalidArgument naming the knob (the core's rules, ssam::settingsError); a new depth test
    // rebuilds the pipelines (the old ones retired until the frames using them completed).
    Status setSettings(const Settings& settings) noexcept;
    // InvalidArgument naming the attribute or binding; a new layout rebuilds the pipelines (the
    // old ones retired likewise).
    Status setVertexLayout(const VertexLayout& vertexLayout) noexcept;
    const VertexLayout& vertexLayout() const noexcept;

    // A host texture the built-in programs may sample (a 2D view in SHADER_READ_ONLY_OPTIMAL, ready
    // for fragment-shader reads when the frame runs: the host's barrier), with the host's sampler
    // or, for VK_NULL_HANDLE, SSAM's linear clamp-to-edge one; `id` is required. destroyTexture
    // retires it: gone once FrameDesc::framesCompleted passes `lastFrameIndex`.
    Status createTexture(VkImageView view, VkSampler sampler, TextureId* id) noexcept;
    Status destroyTexture(TextureId id, std::uint64_t lastFrameIndex) noexcept;

    // Way (a), render(): records the three passes with SSAM's built-in programs.
    // Way (b): the host's own pipelines, one pass at a time, recorded into FrameDesc::commandBuffer.
    // beginFrame checks the frame, (re)creates SSAM's targets and records its per-frame update;
    // each begin...Pass begins SSAM's render pass (viewport and scissor set, nothing bound); the
    // host binds its pipeline (pipelineState()), descriptor sets and buffers and draws; the
    // matching end...Pass ends it; composite() records the composite and ends the frame. Out of
    // order: InvalidCall; an open pass is then ended (the command buffer stays valid) and the frame
    // abandoned.
    // The state the host's pipeline for `pass` must use with the host's colour and depth formats.
    Status pipelineState(FoliagePass pass, VkFormat colorFormat, VkFormat depthFormat,
                         PipelineState* state) const noexcept;
    std::uint64_t pipelineStateVersion() const noexcept;

    // SSAM's intermediates after render(), e.g. to show the paper's Figures 3.6-3.8: images in
    // SHADER_READ_ONLY_OPTIMAL, written at COLOR_ATTACHMENT_OUTPUT (VK_NULL_HANDLE until first used).
    struct Intermediates {
        VkImage mask = VK_NULL_HANDLE;     // r = MAX, a = SUM (R8G8B8A8_UNORM / R16G16B16A16_SFLOAT); Rg16f: MAX in r
        VkImage maskAdd = VK_NULL_HANDLE;  // Rg16f only: SUM in r (R16_SFLOAT)
        VkImage foliage = VK_NULL_HANDLE;  // rt_foliage, the host colour's format
    };
    Intermediates intermediates() const noexcept;

    struct Impl;

private:
    friend HostPasses;  // reaches impl_ and the two messages below
    static constexpr const char* kMovedFrom = "ssam::vk: this ScreenSpaceAlphaMaskVk was moved from (or out of memory)";
    static constexpr const char* kRenderWithoutCallback = "ssam::vk: render() without a draw callback";
    std::unique_ptr<Impl> impl_;
};

}  // namespace ssam::vk
