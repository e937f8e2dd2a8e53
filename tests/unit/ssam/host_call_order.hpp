// SPDX-License-Identifier: MIT
#pragma once
// What the hostile-input tables of ssam::gl and ssam::vk (ssam_gl_hostile_test.cpp,
// ssam_vk_hostile_test.cpp) share: the order of a frame's calls is the core's
// (ssam/src/core/frame_sequence.hpp), so both host APIs refuse the same calls out of order with
// the same messages. A `Sweep` has the API's `ssam`, `frame()` (a good frame), `render(frame)`
// (drawing nothing); a `Hostile` is {name, setup, call, expected status, what its message says}.
#include <functional>
#include <vector>

#include <gtest/gtest.h>

namespace ssam_host_test {

// A frame of way (b) with no draws, whole: the host's targets as they were (the composite blends
// with a mask of 0; nothing writes depth).
template <class Ssam, class Frame>
void emptyFrame(Ssam& ssam, const Frame& frame) {
    using Status = decltype(ssam.composite());
    ASSERT_EQ(ssam.beginFrame(frame), Status::Ok) << ssam.lastMessage();
    ASSERT_EQ(ssam.beginMaskPass(), Status::Ok);
    ASSERT_EQ(ssam.endMaskPass(), Status::Ok);
    ASSERT_EQ(ssam.beginColorPass(), Status::Ok);
    ASSERT_EQ(ssam.endColorPass(), Status::Ok);
    ASSERT_EQ(ssam.composite(), Status::Ok) << ssam.lastMessage();
}

// Every call out of a frame's order, refused (InvalidCall) with where the frame is.
template <class Hostile, class Sweep>
std::vector<Hostile> callsOutOfOrder() {
    using Status = decltype(std::declval<Sweep&>().ssam.composite());
    const Status invalidCall = Status::InvalidCall;
    const std::function<void(Sweep&)> nothing = [](Sweep&) {};
    const std::function<void(Sweep&)> frameBegun = [](Sweep& s) {
        ASSERT_EQ(s.ssam.beginFrame(s.frame()), Status::Ok) << s.ssam.lastMessage();
    };
    return {
        {"beginMaskPass without a frame", nothing, [](Sweep& s) { return s.ssam.beginMaskPass(); }, invalidCall,
         "beginMaskPass called when no frame is open"},
        {"endMaskPass without a frame", nothing, [](Sweep& s) { return s.ssam.endMaskPass(); }, invalidCall,
         "endMaskPass called when no frame is open"},
        {"beginColorPass without a frame", nothing, [](Sweep& s) { return s.ssam.beginColorPass(); }, invalidCall,
         "beginColorPass called when no frame is open"},
        {"endColorPass without a frame", nothing, [](Sweep& s) { return s.ssam.endColorPass(); }, invalidCall,
         "endColorPass called when no frame is open"},
        {"composite without a frame", nothing, [](Sweep& s) { return s.ssam.composite(); }, invalidCall,
         "composite called when no frame is open"},
        {"composite twice", [](Sweep& s) { emptyFrame(s.ssam, s.frame()); },
         [](Sweep& s) { return s.ssam.composite(); }, invalidCall, "composite called when no frame is open"},
        {"render inside an open frame", frameBegun, [](Sweep& s) { return s.render(s.frame()); }, invalidCall,
         "render called when the frame is begun"},
        {"beginFrame inside an open frame", frameBegun, [](Sweep& s) { return s.ssam.beginFrame(s.frame()); },
         invalidCall, "beginFrame called when the frame is begun"},
        {"beginColorPass before the mask pass", frameBegun, [](Sweep& s) { return s.ssam.beginColorPass(); },
         invalidCall, "beginColorPass called when the frame is begun"},
        {"composite before the passes", frameBegun, [](Sweep& s) { return s.ssam.composite(); }, invalidCall,
         "composite called when the frame is begun"},
        {"setSettings inside a frame", frameBegun, [](Sweep& s) { return s.ssam.setSettings({}); }, invalidCall,
         "setSettings() inside a frame"},
    };
}

}  // namespace ssam_host_test
