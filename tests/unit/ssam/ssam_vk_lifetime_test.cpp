// SPDX-License-Identifier: MIT
// Nothing ssam::vk keeps outlives a host object it names: the render-pass path's framebuffers
// over the host's views are made for each frame and destroyed once FrameDesc::framesCompleted
// passes it (frame_scoped.hpp), never found again by the views' handle values, which a host that
// recreates its targets can get back (lavapipe without the layer's handle wrapping does).
#include <cstdint>
#include <cstdio>
#include <map>
#include <set>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <ssam/vk/ssam_vk.hpp>

#include "frame_scoped.hpp"  // ssam/src/vk: Vulkan-free, tested here with fake handles
#include "ssam_vk_support.hpp"
#include "vk_host.hpp"

namespace {

using ssam::vk::Status;
using ssam::vk::detail::FrameScoped;
using namespace ssam_vk_test;

// A fake driver that hands a destroyed object's handle value to the next one made (as lavapipe's
// allocator often does), and what SSAM's beginFrame does with FrameScoped: collect, then a new
// framebuffer for the frame over the host's (fake) views.
struct FakeDevice {
    std::vector<std::uint64_t> freed;
    std::uint64_t next = 0x1000;
    std::set<std::uint64_t> live;
    std::uint64_t make() {
        std::uint64_t h = next++;
        if (!freed.empty()) h = freed.back(), freed.pop_back();
        live.insert(h);
        return h;
    }
    void destroy(std::uint64_t h) {
        ASSERT_EQ(live.erase(h), 1u) << "handle " << h << " destroyed twice or never made";
        freed.push_back(h);
    }
};
struct FakeFramebuffer {
    std::uint64_t handle = 0, colorView = 0, depthView = 0, colorIncarnation = 0;
};

TEST(SsamVkFrameScoped, AnObjectGoesOnlyOnceItsFrameCompleted) {
    FrameScoped<int> kept;
    std::vector<int> destroyed;
    const auto destroy = [&](int object) { destroyed.push_back(object); };
    for (int frame = 0; frame < 4; ++frame) {
        kept.reserveOne();
        kept.add(std::uint64_t(frame), 100 + frame);
    }
    kept.collect(0, destroy);  // nothing completed
    EXPECT_TRUE(destroyed.empty());
    kept.collect(2, destroy);  // frames 0 and 1 completed
    EXPECT_EQ(destroyed, (std::vector<int>{100, 101}));
    EXPECT_EQ(kept.size(), 2u);
    kept.collect(2, destroy);  // the same number again: nothing more
    EXPECT_EQ(destroyed.size(), 2u);
    kept.destroyAll(destroy);  // release(): the device is idle
    EXPECT_EQ(destroyed, (std::vector<int>{100, 101, 102, 103}));
    EXPECT_EQ(kept.size(), 0u);
}

// The host recreates its views after every frame completes, two frames in flight, and its driver
// gives the same handle values back: every frame still gets a framebuffer made for it (never one
// of an earlier frame found by equal handle values), each is destroyed exactly once, after its
// frame completed and never before, and no more are alive than the frames that may still run.
TEST(SsamVkFrameScoped, RepeatedViewHandlesNeverReachAnOldFramebuffer) {
    FakeDevice host, ssam;
    FrameScoped<FakeFramebuffer> kept;
    std::map<std::uint64_t, std::uint64_t> incarnation;       // host view handle -> how many times made
    std::map<std::uint64_t, std::uint64_t> framebufferFrame;  // SSAM's (fake) framebuffer -> its frame
    int repeatedHandles = 0;
    std::uint64_t colorView = 0, depthView = 0, completed = 0;
    std::vector<std::pair<std::uint64_t, std::uint64_t>> viewsInFlight;  // (colour, depth) of frames not completed
    for (std::uint64_t frame = 0; frame < 24; ++frame) {
        if (frame >= 2) {  // the fence of frame - 2 signalled; its views may go now, made anew
            ++completed;
            const auto [c, d] = viewsInFlight.front();
            viewsInFlight.erase(viewsInFlight.begin());
            host.destroy(c);
            host.destroy(d);
        }
        colorView = host.make();
        depthView = host.make();
        if (incarnation[colorView]++ > 0) ++repeatedHandles;
        viewsInFlight.push_back({colorView, depthView});
        // SSAM's beginFrame.
        kept.collect(completed, [&](const FakeFramebuffer& fb) {
            EXPECT_LT(framebufferFrame[fb.handle], completed) << "destroyed before its frame completed";
            ssam.destroy(fb.handle);
        });
        kept.reserveOne();
        const FakeFramebuffer fb{ssam.make(), colorView, depthView, incarnation[colorView]};
        framebufferFrame[fb.handle] = frame;
        kept.add(frame, fb);
        // The frame uses exactly the framebuffer made for it, over the views alive now.
        EXPECT_EQ(fb.colorView, colorView);
        EXPECT_EQ(fb.colorIncarnation, incarnation[colorView]);
        EXPECT_LE(kept.size(), 3u) << "frame " << frame;  // two in flight and this one
    }
    EXPECT_GT(repeatedHandles, 10) << "the fake driver should hand out repeated view handles";
    kept.destroyAll([&](const FakeFramebuffer& fb) { ssam.destroy(fb.handle); });
    EXPECT_TRUE(ssam.live.empty());
}

// The host's targets destroyed and made again at the same size for each of 12 frames, under the
// validation layer with its handle wrapping off (so the driver's own values come back, as they do
// without the layer): each frame renders into the new images (its own colour shows there) and the
// layer is silent. Before framebuffers were made per frame, SSAM began its render pass with a
// framebuffer over destroyed views here.
TEST(SsamVkLifetime, TargetsRecreatedAtTheSameSizeGetFreshFramebuffers) {
    vk_example::VulkanHost host(true, false, {}, /*uniqueHandles=*/false);
    Messages messages;
    {
        ssam::vk::ScreenSpaceAlphaMaskVk ssam;
        ssam.setMessageCallback(Messages::record, &messages);
        ASSERT_EQ(ssam.initialize(describe(host)), Status::Ok) << ssam.lastMessage();
        const CentreQuad quad(host);
        const float background[4] = {0.0f, 0.0f, 0.0f, 1.0f};
        const float colours[3][3] = {{1.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, {0.0f, 0.0f, 1.0f}};
        std::set<VkImageView> viewsSeen;
        int repeatedViews = 0;
        for (std::uint64_t frame = 0; frame < 12; ++frame) {
            SCOPED_TRACE("frame " + std::to_string(frame));
            const Targets t(host, 32, 32);
            if (!viewsSeen.insert(t.color.view).second) ++repeatedViews;
            const float* rgb = colours[frame % 3];
            const VkCommandBuffer cb = host.begin();
            t.clear(cb, background, 1.0f);
            ssam::vk::FrameDesc f = t.frame(cb);
            f.frameIndex = frame;
            f.framesCompleted = frame;  // the previous frame was waited for
            ASSERT_EQ(ssam.render(f, [&](const ssam::vk::FoliageProgram& p) { quad.draw(p, rgb); }), Status::Ok)
                << ssam.lastMessage();
            t.copyOut(cb);
            host.wait(host.submit(cb));
            const std::uint8_t* centre = t.rgba(16, 16);
            EXPECT_EQ(centre[0], rgb[0] * 255.0f);
            EXPECT_EQ(centre[1], rgb[1] * 255.0f);
            EXPECT_EQ(centre[2], rgb[2] * 255.0f);
            EXPECT_EQ(t.rgba(1, 1)[0] + t.rgba(1, 1)[1] + t.rgba(1, 1)[2], 0) << "outside the quad: the background";
            EXPECT_EQ(t.z(16, 16), 0.5f);  // the foliage depth (§3.7)
        }  // the targets go as soon as their frame completed: SSAM needs no call for that
        std::printf("the colour view's handle value came back in %d of 11 recreations\n", repeatedViews);
        vkDeviceWaitIdle(host.device);
        ssam.release();
    }
    EXPECT_THAT(messages.errors, ::testing::IsEmpty());
    for (const std::string& m : host.validationMessages) ADD_FAILURE() << "validation: " << m;
}

}  // namespace
