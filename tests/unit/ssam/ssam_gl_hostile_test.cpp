// SPDX-License-Identifier: MIT
// Hostile input through ssam::gl, one table (ssam::vk's is ssam_vk_hostile_test.cpp): sizes out
// of range (0, negative, 100000, larger than the host's textures), non-finite matrices and
// bounds, wrong formats, calls out of order. Each is refused with a Status other than Ok and a
// message naming the problem, the host's GL state is as it set it, and its colour and depth
// textures are unchanged.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "host_call_order.hpp"
#include "ssam_gl_host.hpp"

namespace {

using namespace engine::render;
using namespace ssam::testing;
using ssam::gl::Status;

constexpr float kNan = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

struct Sweep {
    GlHost& host;
    ssam::gl::ScreenSpaceAlphaMaskGl& ssam;
    ssam::gl::FrameDesc good;
    ssam::gl::FrameDesc small;  // the targets of an 8x8 host frame
    Status render(const ssam::gl::FrameDesc& f) {
        return ssam.render(f, [](const ssam::gl::FoliageProgram&) {});
    }
    const ssam::gl::FrameDesc& frame() const { return good; }
};

struct Hostile {
    const char* name;
    std::function<void(Sweep&)> setup;
    std::function<Status(Sweep&)> call;
    Status expected;
    const char* says;
};

std::function<Status(Sweep&)> renderWith(std::function<void(Sweep&, ssam::gl::FrameDesc&)> change) {
    return [change](Sweep& s) {
        ssam::gl::FrameDesc f = s.good;
        change(s, f);
        return s.render(f);
    };
}
const std::function<void(Sweep&)> kNothing = [](Sweep&) {};

// The default attribute locations changed by `change`, given to setAttributeLocations.
std::function<Status(Sweep&)> locationsWith(std::function<void(ssam::gl::AttributeLocations&)> change) {
    return [change](Sweep& s) {
        ssam::gl::AttributeLocations at;
        change(at);
        return s.ssam.setAttributeLocations(at);
    };
}
const ssam::gl::Box kGoodBox{{-0.5f, -0.5f, 0.25f}, {0.5f, 0.5f, 0.75f}};

std::vector<Hostile> hostileCalls() {
    const Status invalidArgument = Status::InvalidArgument, invalidTexture = Status::InvalidTexture;
    using F = ssam::gl::FrameDesc;
    using L = ssam::gl::AttributeLocations;
    std::vector<Hostile> calls = {
        {"width 0", kNothing, renderWith([](Sweep&, F& f) { f.width = 0; }), invalidArgument,
         "frame size (FrameDesc::width x height) 0x16 is not positive"},
        {"negative height", kNothing, renderWith([](Sweep&, F& f) { f.height = -5; }), invalidArgument,
         "frame size (FrameDesc::width x height) 16x-5 is not positive"},
        {"width 100000", kNothing, renderWith([](Sweep&, F& f) { f.width = 100000; }), invalidTexture,
         "colour texture is 16x16 but the frame is 100000x16"},
        {"frame larger than the host's textures", kNothing, renderWith([](Sweep& s, F& f) {
             f.colorTexture = s.small.colorTexture;
             f.depthTexture = s.small.depthTexture;
         }),
         invalidTexture, "colour texture is 8x8 but the frame is 16x16"},
        {"a depth texture as colour", kNothing,
         renderWith([](Sweep& s, F& f) { f.colorTexture = s.good.depthTexture; }), invalidTexture,
         "has format GL_DEPTH_COMPONENT32F"},
        {"a colour texture as depth", kNothing,
         renderWith([](Sweep& s, F& f) { f.depthTexture = s.good.colorTexture; }), invalidTexture, "GL_RGBA8"},
        {"NaN in viewProj", kNothing, renderWith([](Sweep&, F& f) { f.viewProj[5] = kNan; }), invalidArgument,
         "FrameDesc::viewProj[5] is nan"},
        {"infinity in viewProj", kNothing, renderWith([](Sweep&, F& f) { f.viewProj[12] = kInf; }), invalidArgument,
         "FrameDesc::viewProj[12] is inf"},
        {"bounds count without bounds", kNothing, renderWith([](Sweep&, F& f) { f.foliageBoundsCount = 3; }),
         invalidArgument, "FrameDesc::foliageBoundsCount is 3 but foliageBounds is null"},
        {"NaN in a box", kNothing, renderWith([](Sweep&, F& f) {
             static ssam::gl::Box box = kGoodBox;
             box.min[2] = kNan;
             f.foliageBounds = &box;
             f.foliageBoundsCount = 1;
         }),
         invalidArgument, "FrameDesc::foliageBounds[0] z is [nan, 0.750000] (not finite)"},
        {"a box of negative size", kNothing, renderWith([](Sweep&, F& f) {
             static const ssam::gl::Box boxes[2] = {kGoodBox, {{0.0f, 1.0f, 0.5f}, {1.0f, -1.0f, 0.5f}}};
             f.foliageBounds = boxes;
             f.foliageBoundsCount = 2;
         }),
         invalidArgument, "FrameDesc::foliageBounds[1] has max.y -1.000000 below min.y 1.000000"},
        {"a box left at its default", kNothing, renderWith([](Sweep&, F& f) {
             static const ssam::gl::Box box{};
             f.foliageBounds = &box;
             f.foliageBoundsCount = 1;
         }),
         invalidArgument, "FrameDesc::foliageBounds[0] has zero size in 3 axes"},
        {"render without a draw callback", kNothing,
         [](Sweep& s) { return s.ssam.render(s.good, ssam::gl::ScreenSpaceAlphaMaskGl::DrawFoliage{}, nullptr); },
         invalidArgument, "render() without a draw callback"},
        // The built-in programs' attribute locations (way a); instanceModel takes 4..7.
        {"instance tint inside instanceModel's locations", kNothing, locationsWith([](L& at) { at.instanceTint = 7; }),
         invalidArgument, "attributes.instanceModel (4) and attributes.instanceTint (7) overlap"},
        {"instance tint at location 16", kNothing, locationsWith([](L& at) { at.instanceTint = 16; }), invalidArgument,
         "attributes.instanceTint = 16 is past location 15"},
    };
    for (Hostile& h : ssam_host_test::callsOutOfOrder<Hostile, Sweep>()) calls.push_back(std::move(h));
    return calls;
}

TEST(SsamGlHostileInput, IsRefusedNamedAndChangesNothing) {
    GlHost host;
    auto targets = host.opaque();
    auto small = std::make_unique<FrameTargets>(*host.backend, FrameTargetsDesc{8, 8, 1, Format::RGBA8_UNORM});
    std::vector<std::string> errors;
    const Readback colorBefore = host.backend->readback(targets->color());
    const Readback depthBefore = host.backend->readback(targets->depth());
    for (const Hostile& h : hostileCalls()) {
        SCOPED_TRACE(h.name);
        auto ssam = initializedSsam();  // a fresh SSAM per case
        ssam->setMessageCallback(
            [](void* user, ssam::gl::Severity severity, const char* message) {
                if (severity == ssam::gl::Severity::Error)
                    static_cast<std::vector<std::string>*>(user)->push_back(message);
            },
            &errors);
        Sweep s{host, *ssam, host.frameOf(*targets), host.frameOf(*small)};
        {
            const HostGlState hostState;
            hostState.set();
            h.setup(s);
            errors.clear();
            const Status status = h.call(s);
            EXPECT_EQ(status, h.expected) << ssam::gl::statusName(status) << ": " << ssam->lastMessage();
            EXPECT_NE(status, Status::Ok);
            EXPECT_NE(std::string(ssam->lastMessage()).find(h.says), std::string::npos)
                << "message \"" << ssam->lastMessage() << "\" lacks \"" << h.says << "\"";
            ASSERT_EQ(errors.size(), 1u) << "one error through the callback";
            EXPECT_EQ(errors.back(), ssam->lastMessage());
            hostState.expectRestored();  // SSAM left the host's GL state as it was
        }
        EXPECT_EQ(host.backend->readback(targets->color()).values, colorBefore.values) << "the host's colour changed";
        EXPECT_EQ(host.backend->readback(targets->depth()).values, depthBefore.values) << "the host's depth changed";
    }
}

}  // namespace
