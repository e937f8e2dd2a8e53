// SPDX-License-Identifier: MIT
// Hostile input through ssam::vk, one table: null outputs, sizes out of range, non-finite
// matrices and bounds, frame numbers going back, wrong formats, calls out of order. Each is
// refused with a Status other than Ok and a message naming the problem, and records NOTHING:
// every vkCmd* SSAM resolves goes through a counter (DeviceDesc::getDeviceProcAddr), the
// command buffer is then ended and submitted, the host's colour and depth read back unchanged,
// and the validation layer stays silent.
#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <ssam/vk/ssam_vk.hpp>

#include "host_call_order.hpp"
#include "ssam_vk_support.hpp"
#include "vk_host.hpp"

namespace {

using ssam::vk::Status;
using namespace ssam_vk_test;

// ---- Counting what SSAM records ----------------------------------------------------------------

int recorded = 0;  // vkCmd* calls SSAM made

// One wrapper per entry point (Id keeps two of the same signature apart).
template <int Id, class Fn>
struct Counted;
template <int Id, class... A>
struct Counted<Id, void(VKAPI_PTR*)(A...)> {
    static inline void(VKAPI_PTR* real)(A...) = nullptr;
    static void VKAPI_CALL call(A... a) {
        ++recorded;
        real(a...);
    }
};

template <int Id, class Fn>
PFN_vkVoidFunction wrap(PFN_vkVoidFunction real) {
    Counted<Id, Fn>::real = reinterpret_cast<Fn>(real);
    return reinterpret_cast<PFN_vkVoidFunction>(&Counted<Id, Fn>::call);
}

PFN_vkVoidFunction VKAPI_CALL countingDeviceProcAddr(VkDevice device, const char* name) {
    const PFN_vkVoidFunction real = vkGetDeviceProcAddr(device, name);
    if (!real || std::strncmp(name, "vkCmd", 5) != 0) return real;
#define SSAM_COUNTED(fn) \
    if (std::strcmp(name, "vk" #fn) == 0) return wrap<__LINE__, PFN_vk##fn>(real);
    SSAM_COUNTED(CmdPipelineBarrier)
    SSAM_COUNTED(CmdUpdateBuffer)
    SSAM_COUNTED(CmdClearColorImage)
    SSAM_COUNTED(CmdCopyImage)
    SSAM_COUNTED(CmdBeginRenderPass)
    SSAM_COUNTED(CmdEndRenderPass)
    SSAM_COUNTED(CmdBindPipeline)
    SSAM_COUNTED(CmdBindDescriptorSets)
    SSAM_COUNTED(CmdBindVertexBuffers)
    SSAM_COUNTED(CmdPushConstants)
    SSAM_COUNTED(CmdSetViewport)
    SSAM_COUNTED(CmdSetScissor)
    SSAM_COUNTED(CmdDraw)
    SSAM_COUNTED(CmdBeginRendering)
    SSAM_COUNTED(CmdEndRendering)
#undef SSAM_COUNTED
    ADD_FAILURE() << name << " is not counted: add it to countingDeviceProcAddr";
    return real;
}

// ---- The table -----------------------------------------------------------------------------------

constexpr float kNan = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

struct Sweep;
struct Hostile {
    const char* name;
    std::function<void(Sweep&)> setup;  // before counting: may record (a frame begun, a frame done)
    std::function<Status(Sweep&)> call;
    Status expected;
    const char* says;  // in the message
};

struct Sweep {
    vk_example::VulkanHost& host;
    ssam::vk::ScreenSpaceAlphaMaskVk& ssam;
    const Targets& targets;
    VkCommandBuffer cb = VK_NULL_HANDLE;
    ssam::vk::FrameDesc frame() const { return targets.frame(cb); }
    Status render(const ssam::vk::FrameDesc& f) {
        return ssam.render(f, [](const ssam::vk::FoliageProgram&) {});
    }
};

// A frame changed by `change`, rendered.
std::function<Status(Sweep&)> renderWith(std::function<void(ssam::vk::FrameDesc&)> change) {
    return [change](Sweep& s) {
        ssam::vk::FrameDesc f = s.frame();
        change(f);
        return s.render(f);
    };
}
const std::function<void(Sweep&)> kNothing = [](Sweep&) {};

// The default vertex layout changed by `change`, given to setVertexLayout.
std::function<Status(Sweep&)> layoutWith(std::function<void(ssam::vk::VertexLayout&)> change) {
    return [change](Sweep& s) {
        ssam::vk::VertexLayout layout;
        change(layout);
        return s.ssam.setVertexLayout(layout);
    };
}

const ssam::vk::Box kGoodBox{{-0.5f, -0.5f, 0.25f}, {0.5f, 0.5f, 0.75f}};

std::vector<Hostile> hostileCalls() {
    const Status invalidArgument = Status::InvalidArgument, invalidCall = Status::InvalidCall;
    using F = ssam::vk::FrameDesc;
    using L = ssam::vk::VertexLayout;
    std::vector<Hostile> calls = {
        // FrameDesc, field by field.
        {"null command buffer", kNothing, renderWith([](F& f) { f.commandBuffer = VK_NULL_HANDLE; }), invalidArgument,
         "FrameDesc::commandBuffer is VK_NULL_HANDLE"},
        {"null colour view", kNothing, renderWith([](F& f) { f.colorView = VK_NULL_HANDLE; }), invalidArgument,
         "FrameDesc::colorView is VK_NULL_HANDLE"},
        {"null depth view", kNothing, renderWith([](F& f) { f.depthView = VK_NULL_HANDLE; }), invalidArgument,
         "FrameDesc::depthView is VK_NULL_HANDLE"},
        {"width 0", kNothing, renderWith([](F& f) { f.width = 0; }), invalidArgument, "FrameDesc::width is 0"},
        {"height 0", kNothing, renderWith([](F& f) { f.height = 0; }), invalidArgument, "FrameDesc::height is 0"},
        {"width 100000 (declared so too)", kNothing,
         renderWith([](F& f) { f.width = f.colorImageExtent.width = f.depthImageExtent.width = 100000; }),
         invalidArgument, "FrameDesc::width 100000 is above this device's max"},
        {"height 100000 (declared so too)", kNothing,
         renderWith([](F& f) { f.height = f.colorImageExtent.height = f.depthImageExtent.height = 100000; }),
         invalidArgument, "FrameDesc::height 100000 is above this device's max"},
        {"width -1 as unsigned", kNothing, renderWith([](F& f) { f.width = std::uint32_t(-1); }), invalidArgument,
         "FrameDesc::width 4294967295 is above"},
        {"colour extent not declared", kNothing, renderWith([](F& f) {
             f.colorImageExtent = {0, 0};
         }),
         invalidArgument, "FrameDesc::colorImageExtent is 0x0"},
        {"depth extent not declared", kNothing, renderWith([](F& f) {
             f.depthImageExtent = {16, 0};
         }),
         invalidArgument, "FrameDesc::depthImageExtent is 16x0"},
        {"frame wider than the colour image", kNothing, renderWith([](F& f) {
             f.width = 32;
             f.depthImageExtent.width = 32;
         }),
         invalidArgument, "larger than FrameDesc::colorImageExtent 16x16"},
        {"frame taller than the depth image", kNothing, renderWith([](F& f) {
             f.height = 32;
             f.colorImageExtent.height = 32;
         }),
         invalidArgument, "larger than FrameDesc::depthImageExtent 16x16"},
        {"a colour format SSAM does not take", kNothing,
         renderWith([](F& f) { f.colorFormat = VK_FORMAT_R5G6B5_UNORM_PACK16; }), invalidArgument,
         "colorFormat VK_FORMAT_R5G6B5_UNORM_PACK16 is not"},
        {"a colour format that is no VkFormat", kNothing,
         renderWith([](F& f) { f.colorFormat = static_cast<VkFormat>(123456); }), invalidArgument,
         "colorFormat VkFormat 123456 is not"},
        {"a colour format as depth", kNothing, renderWith([](F& f) { f.depthFormat = VK_FORMAT_R8G8B8A8_UNORM; }),
         invalidArgument, "depthFormat VK_FORMAT_R8G8B8A8_UNORM is not"},
        {"NaN in viewProj", kNothing, renderWith([](F& f) { f.viewProj[5] = kNan; }), invalidArgument,
         "FrameDesc::viewProj[5] is nan"},
        {"infinity in viewProj", kNothing, renderWith([](F& f) { f.viewProj[15] = -kInf; }), invalidArgument,
         "FrameDesc::viewProj[15] is -inf"},
        {"bounds count without bounds", kNothing, renderWith([](F& f) { f.foliageBoundsCount = 2; }), invalidArgument,
         "FrameDesc::foliageBoundsCount is 2 but foliageBounds is null"},
        {"NaN in a box", kNothing, renderWith([](F& f) {
             static ssam::vk::Box boxes[2] = {kGoodBox, kGoodBox};
             boxes[1].max[1] = kNan;
             f.foliageBounds = boxes;
             f.foliageBoundsCount = 2;
         }),
         invalidArgument, "FrameDesc::foliageBounds[1] y is [-0.500000, nan] (not finite)"},
        {"a box of negative size", kNothing, renderWith([](F& f) {
             static const ssam::vk::Box box{{1.0f, 0.0f, 0.5f}, {-1.0f, 1.0f, 0.5f}};
             f.foliageBounds = &box;
             f.foliageBoundsCount = 1;
         }),
         invalidArgument, "FrameDesc::foliageBounds[0] has max.x -1.000000 below min.x 1.000000"},
        {"a box left at its default", kNothing, renderWith([](F& f) {
             static const ssam::vk::Box box{};
             f.foliageBounds = &box;
             f.foliageBoundsCount = 1;
         }),
         invalidArgument, "FrameDesc::foliageBounds[0] has zero size in 3 axes"},
        {"framesCompleted past frameIndex", kNothing, renderWith([](F& f) {
             f.frameIndex = 2;
             f.framesCompleted = 3;
         }),
         invalidArgument, "FrameDesc::framesCompleted 3 is past frameIndex 2"},
        {"frameIndex going back",
         [](Sweep& s) {
             F f = s.frame();
             f.frameIndex = 5;
             ssam_host_test::emptyFrame(s.ssam, f);
         },
         renderWith([](F& f) { f.frameIndex = 4; }), invalidArgument,
         "FrameDesc::frameIndex 4 is below the last frame's 5"},
        {"framesCompleted going back",
         [](Sweep& s) {
             F f = s.frame();
             f.frameIndex = 5;
             f.framesCompleted = 3;
             ssam_host_test::emptyFrame(s.ssam, f);
         },
         renderWith([](F& f) {
             f.frameIndex = 6;
             f.framesCompleted = 2;
         }),
         invalidArgument, "FrameDesc::framesCompleted 2 is below the last frame's 3"},
        {"depthMaskThreshold without depthImage",
         [](Sweep& s) {
             ssam::vk::Settings settings;
             settings.depthMaskThreshold = 0.5f;
             ASSERT_EQ(s.ssam.setSettings(settings), Status::Ok);
         },
         renderWith([](F&) {}), invalidArgument, "FrameDesc::depthImage is null"},
        {"render without a draw callback", kNothing,
         [](Sweep& s) { return s.ssam.render(s.frame(), ssam::vk::ScreenSpaceAlphaMaskVk::DrawFoliage{}, nullptr); },
         invalidArgument, "render() without a draw callback"},
        // Null outputs and unknown objects.
        {"createTexture without an id", kNothing,
         [](Sweep& s) { return s.ssam.createTexture(s.targets.color.view, VK_NULL_HANDLE, nullptr); }, invalidArgument,
         "createTexture() with id null"},
        {"createTexture without a view", kNothing,
         [](Sweep& s) {
             ssam::vk::TextureId id = 9;
             const Status status = s.ssam.createTexture(VK_NULL_HANDLE, VK_NULL_HANDLE, &id);
             EXPECT_EQ(id, 0u);
             return status;
         },
         invalidArgument, "createTexture() with view VK_NULL_HANDLE"},
        {"destroyTexture of no texture", kNothing, [](Sweep& s) { return s.ssam.destroyTexture(7, 0); },
         invalidArgument, "destroyTexture(7): no such texture"},
        {"pipelineState without a PipelineState", kNothing,
         [](Sweep& s) {
             return s.ssam.pipelineState(ssam::vk::FoliagePass::Mask, VK_FORMAT_R8G8B8A8_UNORM, VK_FORMAT_D32_SFLOAT,
                                         nullptr);
         },
         invalidArgument, "pipelineState() without a PipelineState"},
        {"pipelineState of a depth format as colour", kNothing,
         [](Sweep& s) {
             ssam::vk::PipelineState state;
             return s.ssam.pipelineState(ssam::vk::FoliagePass::Color, VK_FORMAT_D32_SFLOAT, VK_FORMAT_D32_SFLOAT,
                                         &state);
         },
         invalidArgument, "colorFormat VK_FORMAT_D32_SFLOAT is not"},
        // What the built-in programs read (way a): the per-instance tint.
        {"instance tint of an integer format", kNothing, layoutWith([](L& l) {
             l.instanceTint = {0, VK_FORMAT_R8G8B8A8_UINT, 0};
         }),
         invalidArgument, "vertexLayout.instanceTint.format VK_FORMAT_R8G8B8A8_UINT is not"},
        {"instance tint of three channels", kNothing, layoutWith([](L& l) {
             l.instanceTint = {0, VK_FORMAT_R32G32B32_SFLOAT, 0};
         }),
         invalidArgument, "vertexLayout.instanceTint.format VK_FORMAT_R32G32B32_SFLOAT is not"},
        {"instance tint on a binding not described", kNothing, layoutWith([](L& l) {
             l.instanceTint = {1, VK_FORMAT_R32G32B32A32_SFLOAT, 0};
         }),
         invalidArgument, "vertexLayout.instanceTint reads binding 1, which vertexLayout.bindings does not describe"},
        // Calls out of order: these, and those every host API refuses alike (callsOutOfOrder).
        {"render after release", [](Sweep& s) { s.ssam.release(); }, [](Sweep& s) { return s.render(s.frame()); },
         invalidCall, "render before initialize()"},
    };
    for (Hostile& h : ssam_host_test::callsOutOfOrder<Hostile, Sweep>()) calls.push_back(std::move(h));
    return calls;
}

TEST(SsamVkHostileInput, IsRefusedNamedAndRecordsNothing) {
    vk_example::VulkanHost host(true);
    ssam::vk::DeviceDesc device = describe(host);
    device.getDeviceProcAddr = countingDeviceProcAddr;
    Messages messages;
    ssam::vk::ScreenSpaceAlphaMaskVk ssam;
    ssam.setMessageCallback(Messages::record, &messages);
    {
        const Targets targets(host, 16, 16);
        const float magenta[4] = {1.0f, 0.0f, 1.0f, 1.0f};  // exact in UNORM: a changed pixel shows
        for (const Hostile& h : hostileCalls()) {
            SCOPED_TRACE(h.name);
            ASSERT_EQ(ssam.initialize(device), Status::Ok) << ssam.lastMessage();  // a fresh SSAM per case
            Sweep s{host, ssam, targets, host.begin()};
            targets.clear(s.cb, magenta, 0.75f);
            h.setup(s);
            const int recordedBefore = recorded;
            const std::size_t errorsBefore = messages.errors.size();
            const Status status = h.call(s);
            EXPECT_EQ(status, h.expected) << ssam::vk::statusName(status) << ": " << ssam.lastMessage();
            EXPECT_NE(status, Status::Ok);
            EXPECT_THAT(ssam.lastMessage(), ::testing::HasSubstr(h.says));
            ASSERT_EQ(messages.errors.size(), errorsBefore + 1) << "one error through the callback";
            EXPECT_EQ(messages.errors.back(), ssam.lastMessage());
            EXPECT_EQ(recorded, recordedBefore) << "SSAM recorded into the host's command buffer";
            // Still a valid command buffer: ended, submitted, the images as cleared.
            targets.copyOut(s.cb);
            host.wait(host.submit(s.cb));
            int changed = 0;
            for (std::uint32_t y = 0; y < targets.height; ++y)
                for (std::uint32_t x = 0; x < targets.width; ++x) {
                    const std::uint8_t* p = targets.rgba(x, y);
                    changed += p[0] != 255 || p[1] != 0 || p[2] != 255 || p[3] != 255 || targets.z(x, y) != 0.75f;
                }
            EXPECT_EQ(changed, 0) << "pixels of the host's colour or depth changed";
            for (const std::string& m : host.validationMessages) ADD_FAILURE() << "validation: " << m;
            host.validationMessages.clear();
        }
        vkDeviceWaitIdle(host.device);
        ssam.release();
    }
    EXPECT_GT(recorded, 0) << "the setups' frames were counted: the counter sees what SSAM records";
    for (const std::string& m : host.validationMessages) ADD_FAILURE() << "validation: " << m;
}

}  // namespace
