// SPDX-License-Identifier: MIT
// ssam::vk's frame, recorded into the host's command buffer: the per-frame update, SSAM's three
// passes on either rendering path, the built-in programs inside them (way a) and the host's
// pipelines (way b).
#include <cmath>
#include <cstring>
#include <string>
#include <utility>

#include "../core/frame_rules.hpp"
#include "ssam/core/passes.hpp"
#include "bounds.hpp"
#include "impl.hpp"

namespace ssam::vk {

using detail::check;
using detail::Constants;
using detail::kFrameBlockSize;

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

bool isColorFormat(VkFormat f) {
    return f == VK_FORMAT_R8G8B8A8_UNORM || f == VK_FORMAT_R8G8B8A8_SRGB || f == VK_FORMAT_B8G8R8A8_UNORM ||
           f == VK_FORMAT_B8G8R8A8_SRGB || f == VK_FORMAT_R16G16B16A16_SFLOAT || f == VK_FORMAT_R32G32B32A32_SFLOAT;
}
bool isDepthFormat(VkFormat f) {
    return f == VK_FORMAT_D16_UNORM || f == VK_FORMAT_X8_D24_UNORM_PACK32 || f == VK_FORMAT_D32_SFLOAT ||
           f == VK_FORMAT_D24_UNORM_S8_UINT || f == VK_FORMAT_D32_SFLOAT_S8_UINT;
}

}  // namespace

VkFormat ScreenSpaceAlphaMaskVk::Impl::maskFormat() const {
    switch (settings.maskPrecision) {
        case MaskPrecision::Rgba8: break;
        case MaskPrecision::Rgba16f: return VK_FORMAT_R16G16B16A16_SFLOAT;
        case MaskPrecision::Rg16f: return detail::kMaskPairFormat;
    }
    return VK_FORMAT_R8G8B8A8_UNORM;
}

void ScreenSpaceAlphaMaskVk::Impl::checkFormat(VkFormat format, VkFormatFeatureFlags needed, const char* what) const {
    VkFormatProperties p;
    vk.GetPhysicalDeviceFormatProperties(device.physicalDevice, format, &p);
    if ((p.optimalTilingFeatures & needed) != needed)
        throw Failure(Status::UnsupportedFeature,
                      "ssam::vk: this device cannot use format " + detail::formatName(format) + " as " + what);
}

void ScreenSpaceAlphaMaskVk::Impl::checkFrame(const FrameDesc& f) const {
    const auto invalid = [](const std::string& what) { return Failure(Status::InvalidArgument, "ssam::vk: " + what); };
    if (!f.commandBuffer) throw invalid("FrameDesc::commandBuffer is VK_NULL_HANDLE");
    if (!f.colorView) throw invalid("FrameDesc::colorView is VK_NULL_HANDLE");
    if (!f.depthView) throw invalid("FrameDesc::depthView is VK_NULL_HANDLE");
    checkSize(f);
    checkFormats(f.colorFormat, f.depthFormat);
    if (const std::string error = ssam::detail::matrixError(f.viewProj, "FrameDesc::viewProj"); !error.empty())
        throw invalid(error);
    if (f.foliageBoundsCount > 0 && !f.foliageBounds)
        throw invalid("FrameDesc::foliageBoundsCount is " + std::to_string(f.foliageBoundsCount) +
                      " but foliageBounds is null");
    for (std::size_t i = 0; i < f.foliageBoundsCount; ++i)
        if (const std::string error = ssam::detail::boxError(f.foliageBounds[i].min, f.foliageBounds[i].max,
                                                             "FrameDesc::foliageBounds[" + std::to_string(i) + "]");
            !error.empty())
            throw invalid(error);
    if (settings.depthMaskThreshold > 0.0f && !f.depthImage)
        throw invalid(
            "FrameDesc::depthImage is null, but Settings::depthMaskThreshold > 0 copies the host's depth (the image "
            "of depthView, with TRANSFER_SRC usage)");
    // Frame numbers decide when SSAM destroys what frames in flight may still use: numbers that go
    // back would have it destroy objects of a frame still running.
    if (f.framesCompleted > f.frameIndex)
        throw invalid("FrameDesc::framesCompleted " + std::to_string(f.framesCompleted) + " is past frameIndex " +
                      std::to_string(f.frameIndex));
    if (lastFrameIndex && f.frameIndex < *lastFrameIndex)
        throw invalid("FrameDesc::frameIndex " + std::to_string(f.frameIndex) + " is below the last frame's " +
                      std::to_string(*lastFrameIndex) + " (frame numbers go up)");
    if (f.framesCompleted < lastFramesCompleted)
        throw invalid("FrameDesc::framesCompleted " + std::to_string(f.framesCompleted) +
                      " is below the last frame's " + std::to_string(lastFramesCompleted) +
                      " (a frame that completed stays completed)");
}

// The frame against what the host declared of its images and against the device's limits
// (VkPhysicalDeviceLimits): SSAM makes its intermediates and framebuffers of the frame's size,
// and renders that much of the host's images.
void ScreenSpaceAlphaMaskVk::Impl::checkSize(const FrameDesc& f) const {
    const auto invalid = [](const std::string& what) { return Failure(Status::InvalidArgument, "ssam::vk: " + what); };
    const auto extent = [](VkExtent2D e) { return std::to_string(e.width) + "x" + std::to_string(e.height); };
    if (f.width == 0 || f.height == 0)
        throw invalid("FrameDesc::" + std::string(f.width == 0 ? "width" : "height") + " is 0 (frame " +
                      std::to_string(f.width) + "x" + std::to_string(f.height) + ")");
    for (const auto& [name, declared] :
         {std::pair{"colorImageExtent", f.colorImageExtent}, std::pair{"depthImageExtent", f.depthImageExtent}}) {
        if (declared.width == 0 || declared.height == 0)
            throw invalid(std::string("FrameDesc::") + name + " is " + extent(declared) +
                          ": declare the extent of the view's image (Vulkan cannot tell SSAM a view's size)");
    }
    struct Limit {
        const char* name;
        std::uint32_t value;
        bool width, height;  // which of the frame's sides it bounds
    };
    const Limit limits[] = {{"maxFramebufferWidth", maxFramebufferWidth, true, false},
                            {"maxFramebufferHeight", maxFramebufferHeight, false, true},
                            {"maxImageDimension2D", maxImageDimension2D, true, true}};
    for (const Limit& l : limits) {
        if (l.width && f.width > l.value)
            throw invalid("FrameDesc::width " + std::to_string(f.width) + " is above this device's " + l.name + " " +
                          std::to_string(l.value));
        if (l.height && f.height > l.value)
            throw invalid("FrameDesc::height " + std::to_string(f.height) + " is above this device's " + l.name + " " +
                          std::to_string(l.value));
    }
    for (const auto& [name, declared] :
         {std::pair{"colorImageExtent", f.colorImageExtent}, std::pair{"depthImageExtent", f.depthImageExtent}})
        if (f.width > declared.width || f.height > declared.height)
            throw invalid("the frame " + std::to_string(f.width) + "x" + std::to_string(f.height) +
                          " (FrameDesc::width x height) is larger than FrameDesc::" + name + " " + extent(declared));
}

void ScreenSpaceAlphaMaskVk::Impl::checkFormats(VkFormat colorFormat, VkFormat depthFormat) const {
    if (!isColorFormat(colorFormat))
        throw Failure(Status::InvalidArgument,
                      "ssam::vk: colorFormat " + detail::formatName(colorFormat) +
                          " is not R8G8B8A8 / B8G8R8A8 UNORM or SRGB, R16G16B16A16_SFLOAT or R32G32B32A32_SFLOAT");
    if (!isDepthFormat(depthFormat))
        throw Failure(Status::InvalidArgument, "ssam::vk: depthFormat " + detail::formatName(depthFormat) +
                                                   " is not D16_UNORM, X8_D24_UNORM_PACK32, D32_SFLOAT, "
                                                   "D24_UNORM_S8_UINT or D32_SFLOAT_S8_UINT");
}

const detail::Generation& ScreenSpaceAlphaMaskVk::Impl::generationFor(const FrameDesc& f) {
    const detail::GenerationKey key{f.colorFormat,
                                    f.depthFormat,
                                    maskFormat(),
                                    f.width,
                                    f.height,
                                    settingsVersion,
                                    settings.depthMaskThreshold > 0.0f};
    if (generation && generation->key == key) return *generation;
    if (!generation || generation->key.colorFormat != key.colorFormat)
        checkFormat(key.colorFormat, VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BLEND_BIT | VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT,
                    "a blended, sampled colour target");
    checkFormat(key.maskFormat, VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BLEND_BIT | VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT,
                "the mask");
    if (key.depthRestore)
        checkFormat(key.depthFormat,
                    VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT | VK_FORMAT_FEATURE_TRANSFER_SRC_BIT |
                        VK_FORMAT_FEATURE_TRANSFER_DST_BIT,
                    "a copied and sampled depth (Settings::depthMaskThreshold)");
    detail::Generation next;
    next.create(vk, memory, shared, key, settings, vertexLayout, dynamic());  // destroys what it made if it fails
    if (generation) {
        auto old = std::make_shared<detail::Generation>(std::move(*generation));
        retired.add(old->lastUsedFrame, [this, old] { old->destroy(vk, memory); });
    }
    generation = std::move(next);
    return *generation;
}

void ScreenSpaceAlphaMaskVk::Impl::updateConstants(const FrameDesc& f, VkCommandBuffer cb) {
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
    constexpr VkPipelineStageFlags kReaders = VK_PIPELINE_STAGE_VERTEX_INPUT_BIT | VK_PIPELINE_STAGE_VERTEX_SHADER_BIT |
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
void ScreenSpaceAlphaMaskVk::Impl::beginPass(const FrameDesc& f, const detail::Generation& g,
                                             const detail::FrameFramebuffers* fb, detail::PassKind pass,
                                             const VkClearValue* clear, VkPipeline pipeline) {
    const VkCommandBuffer cb = f.commandBuffer;
    if (dynamic()) {
        detail::beginDynamicPass(vk, cb, pass, g, {f.colorView, f.depthView, f.depthFormat, f.width, f.height}, clear);
    } else {
        VkRenderPassBeginInfo begin{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
        switch (pass) {
            case detail::PassKind::Mask: begin.renderPass = g.maskPass, begin.framebuffer = fb->mask; break;
            case detail::PassKind::Color: begin.renderPass = g.colorPass, begin.framebuffer = fb->color; break;
            case detail::PassKind::Composite:
                begin.renderPass = g.compositePass, begin.framebuffer = fb->composite;
                break;
            case detail::PassKind::DepthRestore:
                begin.renderPass = g.restorePass, begin.framebuffer = fb->restore;
                break;
        }
        begin.renderArea = {{0, 0}, {f.width, f.height}};
        // `clear` holds one value per colour target (Rg16f's mask pass: two).
        begin.clearValueCount = clear ? (pass == detail::PassKind::Mask && g.key.maskPair() ? 2 : 1) : 0;
        begin.pClearValues = clear;
        vk.CmdBeginRenderPass(cb, &begin, VK_SUBPASS_CONTENTS_INLINE);
    }
    if (pipeline) vk.CmdBindPipeline(cb, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
    const VkViewport viewport{0.0f, 0.0f, float(f.width), float(f.height), 0.0f, 1.0f};
    const VkRect2D scissor{{0, 0}, {f.width, f.height}};
    vk.CmdSetViewport(cb, 0, 1, &viewport);
    vk.CmdSetScissor(cb, 0, 1, &scissor);
}

void ScreenSpaceAlphaMaskVk::Impl::endPass(VkCommandBuffer cb, const detail::Generation& g, detail::PassKind pass) {
    if (dynamic()) detail::endDynamicPass(vk, cb, pass, g);
    else vk.CmdEndRenderPass(cb);
}

namespace {

detail::PassKind kindOf(FoliagePass pass) {
    return pass == FoliagePass::Mask ? detail::PassKind::Mask : detail::PassKind::Color;
}

}  // namespace

void ScreenSpaceAlphaMaskVk::Impl::expect(detail::Phase expected, const char* call) const {
    core::expectPhase("ssam::vk", initialized, phase, expected, call);
}

void ScreenSpaceAlphaMaskVk::Impl::abandonFrame() noexcept {
    // An open pass is ended so that the host's command buffer stays valid.
    if ((phase == detail::Phase::InMaskPass || phase == detail::Phase::InColorPass) && generation)
        endPass(frame.commandBuffer, *generation,
                phase == detail::Phase::InMaskPass ? detail::PassKind::Mask : detail::PassKind::Color);
    phase = detail::Phase::Idle;
    framebuffers = {};
}

void ScreenSpaceAlphaMaskVk::Impl::warnIfFramesDoNotComplete() noexcept {
    constexpr std::size_t kMany = 256;  // far more frames in flight than any host keeps
    if (warnedFramesNotCompleting || frameFramebuffers.size() < kMany) return;
    warnedFramesNotCompleting = true;
    message(Severity::Warning, "ssam::vk: " + std::to_string(frameFramebuffers.size()) +
                                   " frames' framebuffers wait for FrameDesc::framesCompleted (" +
                                   std::to_string(lastFramesCompleted) +
                                   ") to pass them: it must rise as the host's frames complete");
}

FrameReport ScreenSpaceAlphaMaskVk::Impl::beginFrame(const FrameDesc& f) {
    expect(detail::Phase::Idle, "beginFrame");
    checkFrame(f);
    lastFrameIndex = f.frameIndex;
    lastFramesCompleted = f.framesCompleted;
    frameFramebuffers.collect(f.framesCompleted,
                              [this](const detail::FrameFramebuffers& fb) { detail::destroyFramebuffers(vk, fb); });
    retired.collect(f.framesCompleted);
    FrameReport report;
    const std::optional<Rect> visible = detail::compositeRegion(f);
    if (!visible) return report;  // no foliage in view: nothing recorded, not even SSAM's targets made
    detail::Generation& g = const_cast<detail::Generation&>(generationFor(f));
    if (!dynamic()) {
        // New ones every frame, whatever the views' handle values (frame_scoped.hpp).
        frameFramebuffers.reserveOne();
        framebuffers = g.createFramebuffers(vk, f.colorView, f.depthView);
        frameFramebuffers.add(f.frameIndex, framebuffers);
        warnIfFramesDoNotComplete();
    }
    g.lastUsedFrame = f.frameIndex;
    frame = f;
    updateConstants(f, f.commandBuffer);
    phase = detail::Phase::FrameBegun;
    region = *visible;
    report.foliageInView = true;
    report.passesRun = 3;
    report.compositeRegion = region;
    return report;
}

// 1. Mask pass (§3.5.2, Table 3.1): cleared to black; RGB = MAX, A = ADD; depth tested, not written.
// 2. Colour pass (§3.5.3): cleared to the clear colour (§3.6.1); alpha-tested; depth written (§3.7).
// Nothing bound: the host's pipeline (way b) or SSAM's (drawBuiltIn) comes next.
PassInfo ScreenSpaceAlphaMaskVk::Impl::beginFoliagePass(FoliagePass which) {
    const bool mask = which == FoliagePass::Mask;
    expect(mask ? detail::Phase::FrameBegun : detail::Phase::MaskDone, mask ? "beginMaskPass" : "beginColorPass");
    VkClearValue clear[2]{};
    if (!mask)
        for (int i = 0; i < 4; ++i) clear[0].color.float32[i] = settings.foliageClearColor[i];
    const detail::Generation& g = *generation;
    // Settings::depthMaskThreshold: the opaque depth, before the colour pass writes the foliage's.
    if (!mask && g.key.depthRestore) saveOpaqueDepth(g);
    beginPass(frame, g, &framebuffers, kindOf(which), clear, VK_NULL_HANDLE);
    phase = mask ? detail::Phase::InMaskPass : detail::Phase::InColorPass;
    return {which, frame.commandBuffer, mask ? 0.0f : settings.colorAlphaReference, mask && g.key.maskPair() ? 2u : 1u};
}

void ScreenSpaceAlphaMaskVk::Impl::endFoliagePass(FoliagePass which) {
    const bool mask = which == FoliagePass::Mask;
    expect(mask ? detail::Phase::InMaskPass : detail::Phase::InColorPass, mask ? "endMaskPass" : "endColorPass");
    endPass(frame.commandBuffer, *generation, kindOf(which));
    phase = mask ? detail::Phase::MaskDone : detail::Phase::ColorDone;
}

// Way (a) inside an open pass: SSAM's descriptor sets, constants binding and default push
// constants, then the host's draws.
void ScreenSpaceAlphaMaskVk::Impl::drawBuiltIn(const PassInfo& pass, DrawFoliage draw, void* user) {
    const VkCommandBuffer cb = frame.commandBuffer;
    vk.CmdBindPipeline(cb, VK_PIPELINE_BIND_POINT_GRAPHICS,
                       pass.pass == FoliagePass::Mask ? generation->maskPipeline : generation->colorPipeline);
    const VkDescriptorSet sets[] = {frameSet, whiteSet};
    vk.CmdBindDescriptorSets(cb, VK_PIPELINE_BIND_POINT_GRAPHICS, shared.foliageLayout, 0, 2, sets, 0, nullptr);
    const VkDeviceSize offset = 0;
    vk.CmdBindVertexBuffers(cb, vertexLayout.constantsBinding, 1, &constants.buffer, &offset);
    struct {
        float model[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
        float factor[4] = {1, 1, 1, 1};
        std::uint32_t hasTexture = 0;
    } defaults;
    static_assert(sizeof defaults == detail::kFoliagePushSize);
    detail::Recorder recorder{&vk, cb, shared.foliageLayout, &textures, whiteSet};
    recorder.push(0, detail::kFoliagePushSize, &defaults);
    FoliageProgram program;
    program.pass = pass.pass;
    program.commandBuffer = cb;
    program.layout = shared.foliageLayout;
    program.alphaReference = pass.alphaReference;
    program.recorder = &recorder;
    core::runDrawCallback("ssam::vk", pass.pass, [&] { draw(user, program); });
}

// 3. Composite (§3.5.4, Listing 3.2) onto the host's colour.
void ScreenSpaceAlphaMaskVk::Impl::compositeFrame() {
    expect(detail::Phase::ColorDone, "composite");
    const detail::Generation& g = *generation;
    const VkCommandBuffer cb = frame.commandBuffer;
    beginPass(frame, g, &framebuffers, detail::PassKind::Composite, nullptr, g.compositePipeline);
    const VkRect2D scissor{{region.x, region.y}, {std::uint32_t(region.width), std::uint32_t(region.height)}};
    vk.CmdSetScissor(cb, 0, 1, &scissor);  // only where the foliage can be
    vk.CmdBindDescriptorSets(cb, VK_PIPELINE_BIND_POINT_GRAPHICS, shared.compositeLayout, 0, 1, &g.compositeSet, 0,
                             nullptr);
    const core::ColorFade fade = core::colorFadeOf(settings);
    const detail::CompositePush push{settings.maskLerp,
                                     settings.squareMask ? 1u : 0u,
                                     g.key.maskPair() ? 1u : 0u,
                                     settings.depthMaskThreshold,
                                     {fade.start, fade.end},
                                     settings.colorBlur ? 1u : 0u,
                                     0u,
                                     {fade.clearColor[0], fade.clearColor[1], fade.clearColor[2]}};
    vk.CmdPushConstants(cb, shared.compositeLayout, VK_SHADER_STAGE_FRAGMENT_BIT, 0, detail::kCompositePushSize, &push);
    vk.CmdDraw(cb, 3, 1, 0, 0);
    endPass(cb, g, detail::PassKind::Composite);
    if (g.key.depthRestore) restoreDepth(g, push);
    phase = detail::Phase::Idle;
    framebuffers = {};
}

FrameReport ScreenSpaceAlphaMaskVk::Impl::render(const FrameDesc& f, DrawFoliage draw, void* user) {
    expect(detail::Phase::Idle, "render");  // named as the host called it, not as beginFrame
    const FrameReport report = beginFrame(f);
    if (!report.foliageInView) return report;
    for (FoliagePass pass : {FoliagePass::Mask, FoliagePass::Color}) {
        const PassInfo info = beginFoliagePass(pass);
        drawBuiltIn(info, draw, user);
        endFoliagePass(pass);
    }
    compositeFrame();
    return report;
}

// Way (b): the state of SSAM's own pipeline for the pass, and a render pass compatible with its
// (made once per formats, kept until release()).
PipelineState ScreenSpaceAlphaMaskVk::Impl::pipelineStateFor(FoliagePass pass, VkFormat colorFormat,
                                                             VkFormat depthFormat) {
    expectInitialized("pipelineState");
    checkFormats(colorFormat, depthFormat);
    PipelineState state;
    detail::fixedState(kindOf(pass), settings, state);
    const VkFormat target = pass == FoliagePass::Mask ? maskFormat() : colorFormat;
    for (std::uint32_t i = 0; i < state.colorAttachmentCount; ++i) state.colorAttachmentFormats[i] = target;
    state.depthAttachmentFormat = depthFormat;
    state.stencilAttachmentFormat =
        depthFormat == VK_FORMAT_D24_UNORM_S8_UINT || depthFormat == VK_FORMAT_D32_SFLOAT_S8_UINT ? depthFormat
                                                                                                  : VK_FORMAT_UNDEFINED;
    state.version = pipelineStateVersion;
    if (!dynamic()) {
        for (const CompatiblePass& c : compatiblePasses)
            if (c.kind == kindOf(pass) && c.target == target && c.depth == depthFormat) state.renderPass = c.pass;
        if (!state.renderPass) {
            compatiblePasses.reserve(compatiblePasses.size() + 1);  // no throw after the pass exists
            state.renderPass = detail::createPassFor(vk, kindOf(pass), target, depthFormat);
            compatiblePasses.push_back({kindOf(pass), target, depthFormat, state.renderPass});
        }
    }
    return state;
}

}  // namespace ssam::vk
