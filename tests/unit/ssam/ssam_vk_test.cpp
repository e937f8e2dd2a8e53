// SPDX-License-Identifier: MIT
// ssam::vk (ssam/vk/ssam_vk.hpp) in a plain Vulkan host under the validation layer with
// synchronization validation: its errors come back as a Status and a message naming the cause,
// it resolves every function through the host's loader, and a resized frame makes new
// intermediates while the old ones wait for the frames in flight (FrameDesc::framesCompleted),
// with device memory from the host's allocation callback, all given back by release().
// The pictures are checked by the example's tests (SsamVk.* in tests/capture/gl).
#include <cstring>
#include <deque>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <ssam/vk/ssam_vk.hpp>

#include "ssam_vk_support.hpp"
#include "vk_host.hpp"

namespace {

using ssam::vk::ScreenSpaceAlphaMaskVk;
using ssam::vk::Status;
using ssam::vk::statusName;
using ::testing::HasSubstr;

using namespace ssam_vk_test;

class SsamVk : public ::testing::Test {
protected:
    void SetUp() override { ssam.setMessageCallback(Messages::record, &messages); }
    void TearDown() override {
        vkDeviceWaitIdle(host.device);
        ssam.release();
        for (const std::string& m : host.validationMessages) ADD_FAILURE() << "validation: " << m;
    }
    // A render() (drawing nothing) that SSAM must refuse as InvalidArgument: its message, or the
    // status it returned instead (which no expected message contains).
    std::string refusedRender(const ssam::vk::FrameDesc& f) {
        const Status status = ssam.render(f, [](const ssam::vk::FoliageProgram&) {});
        return status == Status::InvalidArgument ? ssam.lastMessage() : std::string("returned ") + statusName(status);
    }
    vk_example::VulkanHost host{true};
    ScreenSpaceAlphaMaskVk ssam;
    Messages messages;
};

// The same, with SSAM initialized on the host's device with the default settings.
class SsamVkInitialized : public SsamVk {
protected:
    void SetUp() override {
        SsamVk::SetUp();
        ASSERT_EQ(ssam.initialize(describe(host)), Status::Ok) << ssam.lastMessage();
    }
};

TEST_F(SsamVk, CallsBeforeInitializeAreInvalid) {
    ssam::vk::FrameDesc frame;
    EXPECT_EQ(ssam.render(frame, [](const ssam::vk::FoliageProgram&) {}), Status::InvalidCall);
    EXPECT_THAT(ssam.lastMessage(), HasSubstr("render before initialize()"));
    ssam::vk::TextureId id = 7;
    EXPECT_EQ(ssam.createTexture(VK_NULL_HANDLE, VK_NULL_HANDLE, &id), Status::InvalidCall);
    EXPECT_EQ(id, 0u);
    ASSERT_EQ(messages.errors.size(), 2u);
}

TEST_F(SsamVk, AnIncompleteDeviceDescriptionIsNamed) {
    ssam::vk::DeviceDesc d = describe(host);
    d.getInstanceProcAddr = nullptr;
    EXPECT_EQ(ssam.initialize(d), Status::InvalidArgument);
    EXPECT_THAT(ssam.lastMessage(), HasSubstr("getInstanceProcAddr"));
}

// Every function comes through the host's loader: one it does not resolve is named.
PFN_vkVoidFunction VKAPI_CALL withoutCmdDraw(VkInstance instance, const char* name) {
    if (std::strcmp(name, "vkCmdDraw") == 0) return nullptr;
    return vkGetInstanceProcAddr(instance, name);
}
PFN_vkVoidFunction VKAPI_CALL withoutDeviceCmdDraw(VkDevice device, const char* name) {
    if (std::strcmp(name, "vkCmdDraw") == 0) return nullptr;
    return vkGetDeviceProcAddr(device, name);
}

TEST_F(SsamVk, AMissingEntryPointIsNamed) {
    ssam::vk::DeviceDesc d = describe(host);
    d.getInstanceProcAddr = withoutCmdDraw;
    d.getDeviceProcAddr = withoutDeviceCmdDraw;
    EXPECT_EQ(ssam.initialize(d), Status::MissingEntryPoint);
    EXPECT_THAT(ssam.lastMessage(), HasSubstr("vkCmdDraw"));
}

TEST_F(SsamVk, BadSettingsAreNamed) {
    ssam::vk::VertexLayout layout;
    layout.position.format = VK_FORMAT_UNDEFINED;
    EXPECT_EQ(ssam.initialize(describe(host), {}, layout), Status::InvalidArgument);
    EXPECT_THAT(ssam.lastMessage(), HasSubstr("vertexLayout.position"));
    layout = {};
    layout.uv = {3, VK_FORMAT_R32G32_SFLOAT, 0};
    EXPECT_EQ(ssam.initialize(describe(host), {}, layout), Status::InvalidArgument);
    EXPECT_THAT(ssam.lastMessage(), HasSubstr("vertexLayout.uv reads binding 3"));
    ssam::vk::Settings s;
    s.maskLerp = 2.0f;
    ASSERT_EQ(ssam.initialize(describe(host)), Status::Ok);
    EXPECT_EQ(ssam.setSettings(s), Status::InvalidArgument);
    EXPECT_THAT(ssam.lastMessage(), HasSubstr("maskLerp"));
}

// The host's device memory callback: what SSAM allocates, by memory object, for the balance.
struct HostMemory {
    vk_example::VulkanHost* host = nullptr;
    std::map<VkDeviceMemory, int> live;
    int allocations = 0;
    static VkResult allocate(void* user, const VkMemoryRequirements& r, VkMemoryPropertyFlags properties,
                             VkDeviceMemory* memory, VkDeviceSize* offset) {
        auto* self = static_cast<HostMemory*>(user);
        VkPhysicalDeviceMemoryProperties p;
        vkGetPhysicalDeviceMemoryProperties(self->host->physical, &p);
        VkMemoryAllocateInfo info{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
        info.allocationSize = r.size;
        for (std::uint32_t i = 0; i < p.memoryTypeCount; ++i)
            if ((r.memoryTypeBits & (1u << i)) && (p.memoryTypes[i].propertyFlags & properties) == properties) {
                info.memoryTypeIndex = i;
                break;
            }
        const VkResult result = vkAllocateMemory(self->host->device, &info, nullptr, memory);
        if (result == VK_SUCCESS) ++self->live[*memory], ++self->allocations;
        *offset = 0;
        return result;
    }
    static void release(void* user, VkDeviceMemory memory, VkDeviceSize) {
        auto* self = static_cast<HostMemory*>(user);
        if (--self->live[memory] == 0) self->live.erase(memory);
        vkFreeMemory(self->host->device, memory, nullptr);
    }
};

TEST_F(SsamVk, AResizeRetiresTheOldIntermediatesUntilTheirFramesComplete) {
    HostMemory memory;
    memory.host = &host;
    ssam::vk::DeviceDesc d = describe(host);
    d.memory = {&memory, HostMemory::allocate, HostMemory::release};
    ASSERT_EQ(ssam.initialize(d), Status::Ok) << ssam.lastMessage();
    const int atStart = memory.allocations;  // the constants buffer and the white texel
    EXPECT_EQ(atStart, 2);
    Targets big(host, 64, 48), small(host, 32, 16);
    FramesInFlight frames{host};
    VkImage previousMask = VK_NULL_HANDLE;
    int maskChanges = 0;
    for (std::uint64_t frame = 0; frame < 6; ++frame) {
        ASSERT_EQ(frames.renderNothing(ssam, frame % 2 == 0 ? big : small, frame), Status::Ok) << ssam.lastMessage();
        if (ssam.intermediates().mask != previousMask) ++maskChanges;
        previousMask = ssam.intermediates().mask;
        // Two images per size change; at most the current ones and those of the two frames in flight.
        EXPECT_LE(memory.live.size(), std::size_t(atStart + 2 * 3)) << "frame " << frame;
    }
    EXPECT_EQ(maskChanges, 6);  // every frame changed the size
    frames.waitForAll();
    ASSERT_EQ(frames.completed, 6u);
    // Everything completed: the next frame (the same size as the last) destroys every retired
    // generation, leaving SSAM's first two allocations and the current mask and rt_foliage.
    ASSERT_EQ(frames.renderNothing(ssam, small, 6), Status::Ok) << ssam.lastMessage();
    EXPECT_EQ(memory.live.size(), std::size_t(atStart + 2));
    frames.waitForAll();
    vkDeviceWaitIdle(host.device);
    ssam.release();
    EXPECT_TRUE(memory.live.empty()) << memory.live.size() << " allocations not given back";
}

TEST_F(SsamVk, DynamicRenderingNeedsTheHostsFeature) {
    ssam::vk::DeviceDesc d = describe(host);  // a device created without dynamicRendering
    d.renderingPath = ssam::vk::RenderingPath::DynamicRendering;
    EXPECT_EQ(ssam.initialize(d), Status::UnsupportedFeature);
    EXPECT_THAT(ssam.lastMessage(), HasSubstr("needs the host's dynamicRendering feature"));
}

// The dynamic-rendering path on a device with the feature: frames of two sizes, two in flight,
// validation silent (its barriers stand in for the render passes' dependencies).
TEST(SsamVkDynamicRendering, FramesOfTwoSizesRecordCleanly) {
    vk_example::VulkanHost host(true, true);
    ScreenSpaceAlphaMaskVk ssam;
    ssam::vk::DeviceDesc d = describe(host);
    d.dynamicRendering = true;
    d.renderingPath = ssam::vk::RenderingPath::DynamicRendering;
    ASSERT_EQ(ssam.initialize(d), Status::Ok) << ssam.lastMessage();
    {
        Targets big(host, 64, 48), small(host, 32, 16);
        FramesInFlight frames{host};
        for (std::uint64_t frame = 0; frame < 4; ++frame)
            ASSERT_EQ(frames.renderNothing(ssam, frame < 2 ? big : small, frame), Status::Ok) << ssam.lastMessage();
        frames.waitForAll();
        vkDeviceWaitIdle(host.device);
    }
    ssam.release();
    for (const std::string& m : host.validationMessages) ADD_FAILURE() << "validation: " << m;
}

// Way (b): the frame's steps in order only; an out-of-order call ends the open pass (the host's
// command buffer stays valid: it is submitted here under validation) and abandons the frame.
TEST_F(SsamVkInitialized, HostPipelineStepsOutOfOrderAreInvalidAndLeaveTheCommandBufferValid) {
    EXPECT_EQ(ssam.beginMaskPass(), Status::InvalidCall);
    EXPECT_THAT(ssam.lastMessage(), HasSubstr("beginMaskPass called when no frame is open"));
    HostFrame h(host, 16, 16);
    ssam::vk::FrameDesc& f = h.frame;
    ASSERT_EQ(ssam.beginFrame(f), Status::Ok) << ssam.lastMessage();
    ssam::vk::PassInfo info;
    ASSERT_EQ(ssam.beginMaskPass(&info), Status::Ok);
    EXPECT_EQ(info.pass, ssam::vk::FoliagePass::Mask);
    EXPECT_EQ(info.commandBuffer, h.cb);
    EXPECT_EQ(info.alphaReference, 0.0f);
    // A query inside the pass does not disturb it, even when refused.
    ssam::vk::PipelineState state;
    EXPECT_EQ(
        ssam.pipelineState(ssam::vk::FoliagePass::Color, VK_FORMAT_R5G6B5_UNORM_PACK16, h.targets.depth.format, &state),
        Status::InvalidArgument);
    EXPECT_EQ(ssam.endMaskPass(), Status::Ok);
    EXPECT_EQ(ssam.composite(), Status::InvalidCall);
    EXPECT_THAT(ssam.lastMessage(), HasSubstr("the mask pass is done (beginColorPass comes next)"));
    EXPECT_EQ(ssam.beginColorPass(), Status::InvalidCall);  // the frame was abandoned
    ASSERT_EQ(ssam.beginFrame(f), Status::Ok);
    ASSERT_EQ(ssam.beginMaskPass(), Status::Ok);
    EXPECT_EQ(ssam.beginFrame(f), Status::InvalidCall);  // ends the open mask pass
    h.submitAndWait();
}

// What the host's pipelines are created with: SSAM's own state, and a version that moves only
// when a setting changes it.
TEST_F(SsamVkInitialized, PipelineStateFollowsTheSettings) {
    ssam::vk::PipelineState mask, color;
    ASSERT_EQ(ssam.pipelineState(ssam::vk::FoliagePass::Mask, VK_FORMAT_R8G8B8A8_UNORM, VK_FORMAT_D32_SFLOAT, &mask),
              Status::Ok);
    ASSERT_EQ(ssam.pipelineState(ssam::vk::FoliagePass::Color, VK_FORMAT_R8G8B8A8_UNORM, VK_FORMAT_D32_SFLOAT, &color),
              Status::Ok);
    // Table 3.1: RGB = MAX, A = ADD; the mask pass tests depth without writing it, the colour pass writes it.
    EXPECT_EQ(mask.colorAttachmentCount, 1u);
    EXPECT_EQ(mask.blendAttachments[0].colorBlendOp, VK_BLEND_OP_MAX);
    EXPECT_EQ(mask.blendAttachments[0].alphaBlendOp, VK_BLEND_OP_ADD);
    EXPECT_EQ(mask.depthStencil.depthWriteEnable, VK_FALSE);
    EXPECT_EQ(color.blendAttachments[0].blendEnable, VK_FALSE);
    EXPECT_EQ(color.depthStencil.depthWriteEnable, VK_TRUE);
    EXPECT_EQ(color.depthStencil.depthCompareOp, VK_COMPARE_OP_LESS);
    EXPECT_EQ(mask.rasterization.cullMode, VK_CULL_MODE_NONE);
    EXPECT_EQ(mask.colorAttachmentFormats[0], VK_FORMAT_R8G8B8A8_UNORM);
    EXPECT_NE(mask.renderPass, VK_NULL_HANDLE);
    const std::uint64_t version = ssam.pipelineStateVersion();
    EXPECT_EQ(mask.version, version);
    ssam::vk::Settings s;
    s.maskLerp = 0.5f;  // the composite's: the passes' state stays
    ASSERT_EQ(ssam.setSettings(s), Status::Ok);
    EXPECT_EQ(ssam.pipelineStateVersion(), version);
    s.depthTest = ssam::vk::DepthTest::Greater;  // reverse-Z
    s.maskPrecision = ssam::vk::MaskPrecision::Rgba16f;
    ASSERT_EQ(ssam.setSettings(s), Status::Ok);
    EXPECT_NE(ssam.pipelineStateVersion(), version);
    ASSERT_EQ(ssam.pipelineState(ssam::vk::FoliagePass::Mask, VK_FORMAT_R8G8B8A8_UNORM, VK_FORMAT_D32_SFLOAT, &mask),
              Status::Ok);
    EXPECT_EQ(mask.depthStencil.depthCompareOp, VK_COMPARE_OP_GREATER);
    EXPECT_EQ(mask.colorAttachmentFormats[0], VK_FORMAT_R16G16B16A16_SFLOAT);
    EXPECT_EQ(mask.version, ssam.pipelineStateVersion());
}

// MaskPrecision::Rg16f: two mask attachments blending differently (MAX, ADD), which needs the
// independentBlend feature; without it the status names the feature, and the settings in force stay.
TEST_F(SsamVk, Rg16fNeedsTheHostsIndependentBlend) {
    ssam::vk::Settings s;
    s.maskPrecision = ssam::vk::MaskPrecision::Rg16f;
    ssam::vk::DeviceDesc d = describe(host);  // independentBlend not declared
    EXPECT_EQ(ssam.initialize(d, s), Status::UnsupportedFeature);
    EXPECT_THAT(ssam.lastMessage(), HasSubstr("maskPrecision Rg16f needs the host's independentBlend feature"));
    ASSERT_EQ(ssam.initialize(d), Status::Ok) << ssam.lastMessage();
    EXPECT_EQ(ssam.setSettings(s), Status::UnsupportedFeature);
    EXPECT_THAT(ssam.lastMessage(), HasSubstr("independentBlend"));
    EXPECT_EQ(ssam.settings().maskPrecision, ssam::vk::MaskPrecision::Rgba8);
}

// Way (b) with Rg16f: the mask pass's state has two attachments (R16_SFLOAT, MAX then ADD), the
// version moves, the colour pass keeps one; the open mask pass says so (PassInfo), and a frame
// of it records cleanly (validation) with both intermediates made.
TEST_F(SsamVk, Rg16fPipelineStateHasTwoMaskAttachments) {
    if (!host.independentBlend) GTEST_SKIP() << "this device has no independentBlend";
    ssam::vk::DeviceDesc d = describe(host);
    d.independentBlend = true;
    ASSERT_EQ(ssam.initialize(d), Status::Ok) << ssam.lastMessage();
    const std::uint64_t version = ssam.pipelineStateVersion();
    ssam::vk::Settings s;
    s.maskPrecision = ssam::vk::MaskPrecision::Rg16f;
    ASSERT_EQ(ssam.setSettings(s), Status::Ok) << ssam.lastMessage();
    EXPECT_NE(ssam.pipelineStateVersion(), version);
    ssam::vk::PipelineState mask, color;
    ASSERT_EQ(ssam.pipelineState(ssam::vk::FoliagePass::Mask, VK_FORMAT_R8G8B8A8_UNORM, VK_FORMAT_D32_SFLOAT, &mask),
              Status::Ok);
    ASSERT_EQ(ssam.pipelineState(ssam::vk::FoliagePass::Color, VK_FORMAT_R8G8B8A8_UNORM, VK_FORMAT_D32_SFLOAT, &color),
              Status::Ok);
    EXPECT_EQ(mask.version, ssam.pipelineStateVersion());
    ASSERT_EQ(mask.colorAttachmentCount, 2u);
    for (int i = 0; i < 2; ++i) {
        EXPECT_EQ(mask.colorAttachmentFormats[i], VK_FORMAT_R16_SFLOAT) << i;
        EXPECT_EQ(mask.blendAttachments[i].blendEnable, VK_TRUE) << i;
        EXPECT_EQ(mask.blendAttachments[i].srcColorBlendFactor, VK_BLEND_FACTOR_ONE) << i;
        EXPECT_EQ(mask.blendAttachments[i].dstColorBlendFactor, VK_BLEND_FACTOR_ONE) << i;
    }
    EXPECT_EQ(mask.blendAttachments[0].colorBlendOp, VK_BLEND_OP_MAX);
    EXPECT_EQ(mask.blendAttachments[1].colorBlendOp, VK_BLEND_OP_ADD);
    EXPECT_NE(mask.renderPass, VK_NULL_HANDLE);
    EXPECT_EQ(color.colorAttachmentCount, 1u);
    EXPECT_EQ(color.colorAttachmentFormats[0], VK_FORMAT_R8G8B8A8_UNORM);

    HostFrame h(host, 16, 16);
    ssam::vk::FrameDesc& f = h.frame;
    ASSERT_EQ(ssam.beginFrame(f), Status::Ok) << ssam.lastMessage();
    ssam::vk::PassInfo info;
    ASSERT_EQ(ssam.beginMaskPass(&info), Status::Ok) << ssam.lastMessage();
    EXPECT_EQ(info.colorAttachmentCount, 2u);
    ASSERT_EQ(ssam.endMaskPass(), Status::Ok);
    ASSERT_EQ(ssam.beginColorPass(&info), Status::Ok);
    EXPECT_EQ(info.colorAttachmentCount, 1u);
    ASSERT_EQ(ssam.endColorPass(), Status::Ok);
    ASSERT_EQ(ssam.composite(), Status::Ok) << ssam.lastMessage();
    EXPECT_NE(ssam.intermediates().maskAdd, VK_NULL_HANDLE);
    h.submitAndWait();
}

// Settings::depthMaskThreshold: a value outside [0, 1] is named; above 0 a frame needs the host's
// depth image (SSAM copies it), and says so.
TEST_F(SsamVk, DepthMaskThresholdNeedsTheDepthImage) {
    ssam::vk::Settings s;
    s.depthMaskThreshold = 1.5f;
    EXPECT_EQ(ssam.initialize(describe(host), s), Status::InvalidArgument);
    EXPECT_THAT(ssam.lastMessage(), HasSubstr("depthMaskThreshold = 1.500000 is outside [0, 1]"));
    s.depthMaskThreshold = 0.5f;
    ASSERT_EQ(ssam.initialize(describe(host), s), Status::Ok) << ssam.lastMessage();
    HostFrame h(host, 8, 8, false);
    ssam::vk::FrameDesc& f = h.frame;
    EXPECT_THAT(refusedRender(f), HasSubstr("FrameDesc::depthImage is null"));
    h.submitAndWait();
}

// FrameDesc::foliageBounds: none in view records nothing (the callback is not called); in view,
// the composite's region is their screen rectangle, rows from the top (Vulkan's y down).
TEST_F(SsamVkInitialized, FoliageBoundsOutOfViewRecordNothing) {
    HostFrame h(host, 64, 64);
    ssam::vk::FrameDesc& f = h.frame;
    const float vulkanViewProj[16] = {1, 0, 0, 0, 0, -1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};  // world y up
    std::memcpy(f.viewProj, vulkanViewProj, sizeof f.viewProj);
    const ssam::vk::Box behind{{-0.5f, -0.5f, -3.0f}, {0.5f, 0.5f, -2.0f}};  // z < 0: behind the camera
    f.foliageBounds = &behind;
    f.foliageBoundsCount = 1;
    int calls = 0;
    ssam::vk::FrameReport report;
    const auto renderCountingCalls = [&] {
        return ssam.render(
            f, [&](const ssam::vk::FoliageProgram&) { ++calls; }, &report);
    };
    ASSERT_EQ(renderCountingCalls(), Status::Ok);
    EXPECT_FALSE(report.foliageInView);
    EXPECT_EQ(report.passesRun, 0);
    EXPECT_EQ(calls, 0);
    EXPECT_EQ(ssam.intermediates().mask, VK_NULL_HANDLE);                  // not even its targets were made
    const ssam::vk::Box topRight{{0.0f, 0.0f, 0.5f}, {1.0f, 1.0f, 0.5f}};  // world x, y >= 0
    f.foliageBounds = &topRight;
    ASSERT_EQ(renderCountingCalls(), Status::Ok);
    EXPECT_TRUE(report.foliageInView);
    EXPECT_EQ(report.passesRun, 3);
    EXPECT_EQ(calls, 2);
    EXPECT_GE(report.compositeRegion.x, 31);  // the right half
    EXPECT_LE(report.compositeRegion.y, 0);   // the top half: rows from the top
    EXPECT_LE(report.compositeRegion.height, 33);
    f.foliageBounds = nullptr;
    EXPECT_THAT(refusedRender(f), HasSubstr("foliageBoundsCount is 1 but foliageBounds is null"));
    h.submitAndWait();
}

TEST_F(SsamVkInitialized, AFrameWithAnUnsupportedFormatIsNamed) {
    HostFrame h(host, 8, 8, false);
    ssam::vk::FrameDesc& f = h.frame;
    f.colorFormat = VK_FORMAT_R5G6B5_UNORM_PACK16;
    EXPECT_THAT(refusedRender(f), HasSubstr("colorFormat"));
    f.colorFormat = h.targets.color.format;
    f.framesCompleted = 3;
    EXPECT_THAT(refusedRender(f), HasSubstr("framesCompleted 3 is past frameIndex 0"));
    h.submitAndWait();
}

TEST_F(SsamVkInitialized, AThrowingDrawCallbackIsReported) {
    HostFrame h(host, 8, 8);
    ssam::vk::FrameDesc& f = h.frame;
    EXPECT_EQ(ssam.render(f, [](const ssam::vk::FoliageProgram&) { throw std::runtime_error("no cards"); }),
              Status::CallbackFailed);
    EXPECT_THAT(ssam.lastMessage(), HasSubstr("threw in the mask pass: no cards"));
    h.submitAndWait();  // the render pass was ended: the command buffer is still valid
}

}  // namespace
