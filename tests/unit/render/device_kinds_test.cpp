// SPDX-License-Identifier: MIT
// The device front end's own contract (device.hpp) and the one table of device kinds
// (create_device.hpp): every kind named once and parsed back, a device made exactly where the
// table says it can be, a driver's extras asked of the right driver only, and pass timings
// named by the passes that produced them even when a pass before them was aborted.
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "expect_error.hpp"  // tests/support
#include "pin_vulkan_libraries.hpp"
#include "engine/render/devices/create_device.hpp"

namespace {

namespace render = engine::render;
using render::DeviceKind;
using ssam::testing::expectError;

TEST(DeviceKinds, EveryKindIsNamedOnceAndParsedBack) {
    std::set<std::string> names;
    for (const render::DeviceKindInfo& k : render::deviceKinds()) {
        EXPECT_TRUE(names.insert(k.name).second) << k.name << " named twice";
        EXPECT_EQ(render::parseDeviceKind(k.name), k.kind);
        EXPECT_EQ(std::string(render::deviceKindInfo(k.kind).name), k.name);
        EXPECT_NE(std::string(k.summary), "");
    }
    EXPECT_EQ(render::deviceKindNames(), "soft|gl|gles|vk");
    EXPECT_FALSE(render::parseDeviceKind("auto"));
    EXPECT_FALSE(render::parseDeviceKind("GL"));
}

// Whatever this machine has: a kind the table calls available is made, one it does not is
// refused by createDevice too, and each device runs the driver its row names. (The Vulkan kind
// loads lavapipe: pinned first under the sanitizers, as the Vulkan test programs do.)
TEST(DeviceKinds, AKindIsMadeExactlyWhereTheTableSaysItCanBe) {
    test_support::pinVulkanLibrariesForLeakSanitizer();
    EXPECT_EQ(render::deviceUnavailableReason(DeviceKind::Soft), "");
    for (const render::DeviceKindInfo& k : render::deviceKinds()) {
        render::DeviceOptions options;
        options.threads = 2;
        const std::string reason = render::deviceUnavailableReason(k.kind, options);
        if (!reason.empty()) {
            EXPECT_THROW(render::createDevice(k.kind, options), engine::Error) << k.name << ": " << reason;
            continue;
        }
        const auto device = render::createDevice(k.kind, options);
        EXPECT_EQ(device->name(), k.name);
        EXPECT_EQ(device->driver().describe().rfind(std::string(k.name) + ":", 0), 0u) << device->driver().describe();
    }
    render::DeviceOptions two;
    two.threads = 2;
    const auto soft = render::createDevice(DeviceKind::Soft, two);
    EXPECT_EQ(render::soft::softDriver(*soft).options().threads, 2);
}

TEST(Device, ADriversExtrasAreAskedOfThatDriverOnly) {
    const auto soft = render::createDevice(DeviceKind::Soft);
    expectError([&] { render::gl::glDriver(*soft); }, "the soft driver");
    expectError([&] { render::vk::vulkanDriver(*soft); }, "the soft driver");
    expectError([&] { render::gl::importTexture(*soft, 1, {"host", 4, 4}); }, "the soft driver");
    EXPECT_FALSE(soft->present(soft->createTexture({"shown", 4, 4})));  // soft has no window
}

TEST(Device, TimingsAreNamedByTheirPassesAcrossAnAbortedOne) {
    const auto gfx = render::createDevice(DeviceKind::Soft);
    const render::TextureHandle target =
        gfx->createTexture({"target", 8, 8, render::Format::RGBA8_UNORM, 1, 1, render::UsageRenderTarget});
    auto pass = [&](const char* name) {
        render::PassDesc p;
        p.name = name;
        p.color[0].texture = target;
        return p;
    };
    gfx->beginPass(pass("first"));
    gfx->endPass();
    gfx->beginPass(pass("aborted"));
    gfx->abortPass();
    gfx->beginPass(pass("third"));
    gfx->endPass();
    const std::vector<render::PassTiming> timings = gfx->takeTimings();
    ASSERT_EQ(timings.size(), 2u);
    EXPECT_EQ(timings[0].pass, "first");
    EXPECT_EQ(timings[1].pass, "third");
    EXPECT_TRUE(gfx->takeTimings().empty());
    gfx->beginPass(pass("open"));
    expectError([&] { gfx->takeTimings(); }, "while pass 'open' is open");
    expectError([&] { gfx->readback(target); }, "while pass 'open' is open");
    gfx->endPass();
}

}  // namespace
